#pragma once
// An enumeration's spellings as one table read both ways: the .cpp that
// defines an enum's toString and its parser keeps the table, so the names
// written, the names read and the names listed in error messages cannot drift.
// Reading ignores case and '-' versus '_'; an alias table next to an enum's
// table adds other common spellings, which read as the canonical value (so
// sessions are written with the table's name).

#include <cassert>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "core/base/names.hpp"

namespace morphogen {

template <class E> struct EnumName {
    E value;
    const char* name;
};

// Another spelling of a value ("gray" for "grey"); never written, never listed.
template <class E> struct EnumAlias {
    const char* alias;
    E value;
};

// "a, b, c": names as error messages list what is accepted.
template <class Range> std::string joinNames(const Range& names) {
    std::string list;
    for (const auto& name : names)
        list += (list.empty() ? "" : ", ") + std::string(name);
    return list;
}

template <class E, std::size_t N> std::string nameOf(const EnumName<E> (&names)[N], E value) {
    for (const EnumName<E>& n : names)
        if (n.value == value)
            return n.name;
    assert(false && "every enumerator has a name in its table");
    return names[0].name;
}

template <class E, std::size_t N>
std::optional<E> valueNamed(const EnumName<E> (&names)[N], std::string_view name) {
    for (const EnumName<E>& n : names)
        if (sameSpelling(name, n.name))
            return n.value;
    return std::nullopt;
}

template <class E, std::size_t N, std::size_t M>
std::optional<E> valueNamed(const EnumName<E> (&names)[N], const EnumAlias<E> (&aliases)[M],
                            std::string_view name) {
    if (const std::optional<E> value = valueNamed(names, name))
        return value;
    for (const EnumAlias<E>& a : aliases)
        if (sameSpelling(name, a.alias))
            return a.value;
    return std::nullopt;
}

template <class E, std::size_t N> std::string nameList(const EnumName<E> (&names)[N]) {
    const char* spellings[N];
    for (std::size_t i = 0; i < N; ++i)
        spellings[i] = names[i].name;
    return joinNames(spellings);
}

} // namespace morphogen
