#include "core/io/output_files.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>

#include <unistd.h>

#include "core/base/errors.hpp"

namespace morphogen {

namespace fs = std::filesystem;

namespace {

// The temporaries a signal handler removes live in fixed slots: the handler
// may not allocate, lock or walk a std::set. A slot is claimed (CAS from
// free) before its path is copied in and published as live after, so the
// handler only reads complete paths. Once a handler has started,
// g_signalCleaning makes claims back off, so a slot it is reading is never
// rewritten under it (the process ends right after). A temporary without a
// slot (all taken, path too long) is still removed on exceptions.
constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
constexpr std::size_t kStemBytes = 64;
constexpr std::size_t kExtBytes = 32;
enum : int { kFree = 0, kClaimed = 1, kLive = 2 };

struct Slot {
    std::atomic<int> state{kFree};
    // -1: `path` is a file. n >= 0: `path` is a StagedSequence's folder,
    // holding stem + index + ext for indexes 0..n (n may be half-written).
    std::atomic<int> sequence{-1};
    char path[kPathBytes];
    char stem[kStemBytes];
    char ext[kExtBytes];
};

Slot g_slots[kSlots];
std::atomic<int> g_signalCleaning{0};
std::atomic<unsigned> g_counter{0};

// Staged temporaries and their final paths, for writeFileAtomically's
// write-in-place rule and for messages (normal context only).
std::mutex g_stagedMutex;
std::map<std::string, std::string>& stagedNames() {
    static std::map<std::string, std::string> names;
    return names;
}

bool copyBounded(char* to, std::size_t size, const std::string& from) {
    if (from.size() + 1 > size)
        return false;
    std::memcpy(to, from.c_str(), from.size() + 1);
    return true;
}

int claimSlot(const std::string& path, int sequence, const std::string& stem = "",
              const std::string& ext = "") {
    if (path.size() + 1 > kPathBytes || stem.size() + 1 > kStemBytes || ext.size() + 1 > kExtBytes)
        return -1;
    for (int i = 0; i < kSlots; ++i) {
        Slot& s = g_slots[i];
        int expected = kFree;
        if (!s.state.compare_exchange_strong(expected, kClaimed))
            continue;
        if (g_signalCleaning.load()) {
            s.state.store(kFree);
            return -1;
        }
        copyBounded(s.path, kPathBytes, path);
        copyBounded(s.stem, kStemBytes, stem);
        copyBounded(s.ext, kExtBytes, ext);
        s.sequence.store(sequence);
        s.state.store(kLive);
        return i;
    }
    return -1;
}

void releaseSlot(int slot) {
    if (slot >= 0)
        g_slots[slot].state.store(kFree);
}

void addStaged(const std::string& temporary, const std::string& path) {
    const std::lock_guard<std::mutex> lock(g_stagedMutex);
    stagedNames()[temporary] = path;
}

void removeStaged(const std::string& temporary) {
    const std::lock_guard<std::mutex> lock(g_stagedMutex);
    stagedNames().erase(temporary);
}

bool isStaged(const std::string& path) {
    const std::lock_guard<std::mutex> lock(g_stagedMutex);
    return stagedNames().count(path) != 0;
}

// Appends `text` to `out` at `*at` (bounded); async-signal-safe.
void append(char* out, std::size_t size, std::size_t* at, const char* text) {
    for (; *text && *at + 1 < size; ++text)
        out[(*at)++] = *text;
    out[*at] = '\0';
}

// `index` with at least five digits, as "%05d" writes it; async-signal-safe.
void appendIndex(char* out, std::size_t size, std::size_t* at, int index) {
    char digits[16];
    int n = 0;
    unsigned v = unsigned(index);
    do {
        digits[n++] = char('0' + v % 10);
        v /= 10;
    } while (v != 0);
    while (n < 5)
        digits[n++] = '0';
    char text[17];
    for (int i = 0; i < n; ++i)
        text[i] = digits[n - 1 - i];
    text[n] = '\0';
    append(out, size, at, text);
}

std::string indexName(const std::string& stem, int index, const std::string& ext) {
    char buffer[kStemBytes + kExtBytes + 24];
    std::size_t at = 0;
    buffer[0] = '\0';
    append(buffer, sizeof buffer, &at, stem.c_str());
    appendIndex(buffer, sizeof buffer, &at, index);
    append(buffer, sizeof buffer, &at, ext.c_str());
    return buffer;
}

std::string errnoText() {
    return errno != 0 ? std::string(": ") + std::strerror(errno) : std::string();
}

} // namespace

std::string finalPathOf(const std::string& path) {
    const std::lock_guard<std::mutex> lock(g_stagedMutex);
    const auto it = stagedNames().find(path);
    return it == stagedNames().end() ? path : it->second;
}

std::string temporaryPathFor(const std::string& path) {
    const fs::path p(path);
    const std::string ext = p.extension().string();
    std::string stem = p.stem().string();
    const std::string suffix =
        "." + std::to_string(::getpid()) + "-" + std::to_string(g_counter.fetch_add(1)) + ext;
    constexpr std::size_t kNameMax = 255;
    const std::size_t room = kNameMax > suffix.size() + 2 ? kNameMax - suffix.size() - 2 : 0;
    if (stem.size() > room)
        stem.resize(room);
    return (p.parent_path() / (".~" + stem + suffix)).string();
}

OutputFiles::~OutputFiles() {
    for (Entry& e : m_entries) {
        if (e.temporary.empty())
            continue;
        std::error_code ec;
        fs::remove(e.temporary, ec);
        releaseSlot(e.slot);
        removeStaged(e.temporary);
    }
}

std::string OutputFiles::stage(const std::string& path) {
    const fs::path key = fs::absolute(path).lexically_normal();
    for (const Entry& e : m_entries)
        if (fs::absolute(e.path).lexically_normal() == key)
            throw InputError(path + ": this run would write it twice (as two of its outputs); "
                                    "give each output its own path");
    Entry e{path, temporaryPathFor(path), -1};
    e.slot = claimSlot(e.temporary, -1);
    addStaged(e.temporary, path);
    m_entries.push_back(e);
    return e.temporary;
}

void OutputFiles::commit() {
    if (m_done)
        return;
    for (const Entry& e : m_entries) {
        std::error_code ec;
        if (!fs::is_regular_file(e.temporary, ec))
            throw std::runtime_error(e.path + ": its file was not written");
        if (fs::is_directory(e.path, ec))
            throw InputError(e.path + ": cannot write here: it is a folder");
    }
    std::string replaced;
    for (Entry& e : m_entries) {
        std::error_code ec;
        fs::rename(e.temporary, e.path, ec);
        if (ec)
            throw InputError(
                e.path + ": cannot move the file into place: " + ec.message() +
                (replaced.empty() ? "; nothing was replaced" : "; already replaced: " + replaced));
        releaseSlot(e.slot);
        removeStaged(e.temporary);
        e.temporary.clear();
        replaced += (replaced.empty() ? "" : ", ") + e.path;
    }
    m_done = true;
}

std::vector<std::string> OutputFiles::paths() const {
    std::vector<std::string> paths;
    for (const Entry& e : m_entries)
        paths.push_back(e.path);
    return paths;
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& temporary)>& write) {
    if (isStaged(path)) {
        write(path);
        return;
    }
    OutputFiles one;
    write(one.stage(path));
    one.commit();
}

void writeTextAtomically(const std::string& path, const std::string& text) {
    const std::string shown = finalPathOf(path);
    writeFileAtomically(path, [&](const std::string& temporary) {
        errno = 0;
        std::ofstream out(temporary, std::ios::binary);
        if (!out)
            throw InputError(shown + ": cannot write the file (is the folder writable?)" +
                             errnoText());
        out << text;
        out.close();
        if (!out)
            throw InputError(shown + ": writing the file failed" + errnoText());
    });
}

StagedSequence::StagedSequence(const std::string& folder, const std::string& stem,
                               const std::string& ext)
    : m_folder(folder), m_stem(stem), m_ext(ext) {
    m_staging = (fs::path(folder) / (".~" + stem + "staging." + std::to_string(::getpid()) + "-" +
                                     std::to_string(g_counter.fetch_add(1))))
                    .string();
    std::error_code ec;
    fs::create_directory(m_staging, ec);
    if (ec)
        throw InputError(folder +
                         ": cannot create a folder in it for the new files: " + ec.message());
    m_slot = claimSlot(m_staging, 0, stem, ext);
}

StagedSequence::~StagedSequence() {
    if (m_done)
        return;
    std::error_code ec;
    fs::remove_all(m_staging, ec);
    releaseSlot(m_slot);
}

std::string StagedSequence::name(int index) const {
    return indexName(m_stem, index, m_ext);
}

std::string StagedSequence::path(int index) const {
    return (fs::path(m_staging) / name(index)).string();
}

std::string StagedSequence::finalPath(int index) const {
    return (fs::path(m_folder) / name(index)).string();
}

void StagedSequence::written(int index) {
    m_count = std::max(m_count, index + 1);
    if (m_slot >= 0)
        g_slots[m_slot].sequence.store(m_count);
}

void StagedSequence::commit() {
    if (m_done)
        return;
    std::error_code ec;
    // The previous series: stem, digits, ext (what this class names).
    for (const fs::directory_entry& e : fs::directory_iterator(m_folder, ec)) {
        const std::string n = e.path().filename().string();
        if (n.size() < m_stem.size() + 5 + m_ext.size() || n.compare(0, m_stem.size(), m_stem) ||
            n.compare(n.size() - m_ext.size(), m_ext.size(), m_ext))
            continue;
        const std::string digits = n.substr(m_stem.size(), n.size() - m_stem.size() - m_ext.size());
        if (std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
            fs::remove(e.path(), ec);
    }
    for (int i = 0; i < m_count; ++i) {
        fs::rename(path(i), finalPath(i), ec);
        if (ec)
            throw InputError(finalPath(i) + ": cannot move the file into place: " + ec.message());
    }
    fs::remove_all(m_staging, ec);
    releaseSlot(m_slot);
    m_done = true;
}

void removeTemporariesForSignal() {
    g_signalCleaning.store(1);
    // Files first: a sequence's folder can only go once the half-written file
    // in it has.
    for (Slot& s : g_slots)
        if (s.state.load() == kLive && s.sequence.load() < 0)
            ::unlink(s.path);
    for (Slot& s : g_slots) {
        const int last = s.sequence.load();
        if (s.state.load() != kLive || last < 0)
            continue;
        char file[kPathBytes + kStemBytes + kExtBytes + 24];
        for (int i = 0; i <= last; ++i) {
            std::size_t at = 0;
            file[0] = '\0';
            append(file, sizeof file, &at, s.path);
            append(file, sizeof file, &at, "/");
            append(file, sizeof file, &at, s.stem);
            appendIndex(file, sizeof file, &at, i);
            append(file, sizeof file, &at, s.ext);
            ::unlink(file);
        }
        ::rmdir(s.path);
    }
}

int liveTemporaryCount() {
    int n = 0;
    for (const Slot& s : g_slots)
        n += s.state.load() == kLive ? 1 : 0;
    return n;
}

} // namespace morphogen
