#pragma once
// Numbers typed on the command line, checked the same way for every flag:
// flags whose values have a range are read as text and parsed here, so that a
// negative, non-finite or out-of-range value is refused with a message naming
// the flag and the accepted range (exit 2) rather than taken for "not given"
// or wrapped by a conversion.

#include <string>

namespace morphogen::cli {

// A whole number in [min, max]; throws InputError "FLAG 'TEXT': accepted are
// whole numbers MIN..MAX" (with `hint` appended) for anything else.
long long integerFlag(const std::string& flag, const std::string& text, long long min,
                      long long max, const std::string& hint = "");

// A finite number in [min, max]; throws InputError naming the flag and range.
double numberFlag(const std::string& flag, const std::string& text, double min, double max,
                  const std::string& hint = "");

} // namespace morphogen::cli
