#include "core/io/output_files.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

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

// A process id that no longer runs (not ours, and kill(0) says no such process).
bool processGone(long pid) {
    if (pid <= 0 || pid == long(::getpid()))
        return false;
    return ::kill(pid_t(pid), 0) != 0 && errno == ESRCH;
}

// The process id in a name this file's writers made, else 0: temporaries
// ".~stem.PID-N.ext", staged series ".~stemstaging.PID-N", commit journals
// ".~commit.PID-N.journal" and checkWritable's probes ".~probe.PID".
long writerPidOf(const std::string& name) {
    static const std::regex temporary(R"(^\.~.*\.([0-9]{1,9})-[0-9]+(\.[^.]*)?$)");
    static const std::regex probe(R"(^\.~probe\.([0-9]{1,9})$)");
    std::smatch m;
    if (std::regex_match(name, m, temporary) || std::regex_match(name, m, probe))
        return std::stol(m[1].str());
    return 0;
}

bool isJournalName(const std::string& name) {
    return name.rfind(".~commit.", 0) == 0 && fs::path(name).extension() == ".journal";
}

std::string folderOf(const std::string& path) {
    return fs::absolute(path).parent_path().lexically_normal().string();
}

// An exclusive flock on a folder, for as long as it lives (best effort: a
// file system without flock just goes unlocked).
class FolderLock {
public:
    explicit FolderLock(const std::string& folder) {
        m_fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (m_fd >= 0)
            while (::flock(m_fd, LOCK_EX) != 0 && errno == EINTR) {
            }
    }
    ~FolderLock() {
        if (m_fd >= 0)
            ::close(m_fd); // releases the lock
    }
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

private:
    int m_fd = -1;
};

// Locks in one order (sorted paths) whatever the caller's, so two commits
// over the same folders cannot wait on each other.
std::vector<std::unique_ptr<FolderLock>> lockFolders(std::vector<std::string> folders) {
    std::sort(folders.begin(), folders.end());
    folders.erase(std::unique(folders.begin(), folders.end()), folders.end());
    std::vector<std::unique_ptr<FolderLock>> locks;
    for (const std::string& f : folders)
        locks.push_back(std::make_unique<FolderLock>(f));
    return locks;
}

// A journal: the set's files (temporary -> final path) and every copy of the
// journal (one in each folder the set writes to, so the next run to any of
// them finds it). Absolute paths.
struct Journal {
    std::vector<std::pair<std::string, std::string>> files;
    std::vector<std::string> copies;
};

std::string journalText(const Journal& j) {
    nlohmann::json files = nlohmann::json::array();
    for (const auto& [temporary, path] : j.files)
        files.push_back({temporary, path});
    return nlohmann::json{{"morphogen_commit", 1}, {"files", files}, {"journals", j.copies}}
               .dump() +
           "\n";
}

// A journal as written, or nothing when it is unreadable or incomplete (its
// run was killed while writing it: no rename had begun).
std::optional<Journal> readJournal(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("files") || !j.contains("journals"))
        return std::nullopt;
    Journal journal;
    try {
        for (const nlohmann::json& f : j.at("files"))
            journal.files.emplace_back(f.at(0).get<std::string>(), f.at(1).get<std::string>());
        for (const nlohmann::json& c : j.at("journals"))
            journal.copies.push_back(c.get<std::string>());
    } catch (const nlohmann::json::exception&) {
        return std::nullopt;
    }
    return journal;
}

// A file this user owns (what the clean-up may touch in a shared folder).
bool ownedByMe(const fs::path& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0 && st.st_uid == ::geteuid();
}

// Whether a journal describes what this file's commit writes, and nothing
// else: a regular file, each temporary named for the journal's process and
// beside its final path, each copy a journal name: a forged journal moves
// nothing.
bool trustworthy(const fs::path& path, const Journal& journal) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
        return false;
    const long pid = writerPidOf(path.filename().string());
    for (const auto& [temporary, final] : journal.files) {
        const fs::path t(temporary), f(final);
        if (!t.is_absolute() || t.parent_path() != f.parent_path() ||
            writerPidOf(t.filename().string()) != pid)
            return false;
    }
    for (const std::string& copy : journal.copies)
        if (!isJournalName(fs::path(copy).filename().string()))
            return false;
    return true;
}

// Finishes a killed run's commit: every temporary still there is moved into
// place (all were complete before the journal was written), then the
// journal's copies go.
void finishJournal(const fs::path& path) {
    if (!ownedByMe(path))
        return; // another user's: theirs to finish
    const std::optional<Journal> journal = readJournal(path);
    std::error_code ec;
    if (!journal) {
        fs::remove(path, ec); // killed while writing it: no rename had begun
        return;
    }
    if (!trustworthy(path, *journal))
        return;
    std::vector<std::string> folders;
    for (const auto& [temporary, final] : journal->files)
        folders.push_back(folderOf(final));
    const auto locks = lockFolders(folders);
    if (!fs::exists(path, ec))
        return; // another run finished it meanwhile
    for (const auto& [temporary, final] : journal->files)
        if (fs::is_regular_file(temporary, ec))
            fs::rename(temporary, final, ec);
    for (const std::string& copy : journal->copies)
        fs::remove(copy, ec);
    fs::remove(path, ec);
}

std::mutex g_recoveredMutex;
std::set<std::string>& recoveredFolders() {
    static std::set<std::string> folders;
    return folders;
}

// recoverInterruptedOutput, once per folder per process.
void recoverOnce(const std::string& folder) {
    const std::string key = fs::absolute(folder).lexically_normal().string();
    {
        const std::lock_guard<std::mutex> lock(g_recoveredMutex);
        if (!recoveredFolders().insert(key).second)
            return;
    }
    recoverInterruptedOutput(key);
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
    recoverOnce(folderOf(path));
    Entry e{path, temporaryPathFor(path), -1};
    e.slot = claimSlot(e.temporary, -1);
    addStaged(e.temporary, path);
    m_entries.push_back(e);
    return e.temporary;
}

void OutputFiles::commit(const std::function<void(int renamed)>& afterRename) {
    if (m_done)
        return;
    for (const Entry& e : m_entries) {
        std::error_code ec;
        if (!fs::is_regular_file(e.temporary, ec))
            throw std::runtime_error(e.path + ": its file was not written");
        if (fs::is_directory(e.path, ec))
            throw InputError(e.path + ": cannot write here: it is a folder");
    }
    std::vector<std::string> folders;
    for (const Entry& e : m_entries)
        folders.push_back(folderOf(e.path));
    const auto locks = lockFolders(folders);

    // A set of several files is journalled first: a kill between two renames
    // is finished by the next run (recoverInterruptedOutput).
    Journal journal;
    if (m_entries.size() > 1) {
        for (const Entry& e : m_entries)
            journal.files.emplace_back(fs::absolute(e.temporary).lexically_normal().string(),
                                       fs::absolute(e.path).lexically_normal().string());
        std::sort(folders.begin(), folders.end());
        folders.erase(std::unique(folders.begin(), folders.end()), folders.end());
        const std::string name = ".~commit." + std::to_string(::getpid()) + "-" +
                                 std::to_string(g_counter.fetch_add(1)) + ".journal";
        for (const std::string& f : folders)
            journal.copies.push_back((fs::path(f) / name).string());
    }
    const auto removeJournals = [&] {
        std::error_code ec;
        for (const std::string& copy : journal.copies)
            fs::remove(copy, ec);
    };
    const std::string text = journalText(journal);
    for (const std::string& copy : journal.copies) {
        std::ofstream out(copy, std::ios::binary);
        out << text;
        out.close();
        std::error_code ec;
        if (!out || fs::file_size(copy, ec) != text.size()) {
            removeJournals();
            throw InputError(finalPathOf(m_entries.front().path) +
                             ": cannot record the files to replace in " + copy +
                             " (is the disk full?); nothing was replaced");
        }
    }

    std::string replaced;
    int renamed = 0;
    for (Entry& e : m_entries) {
        std::error_code ec;
        fs::rename(e.temporary, e.path, ec);
        if (ec) {
            removeJournals();
            throw InputError(
                e.path + ": cannot move the file into place: " + ec.message() +
                (replaced.empty() ? "; nothing was replaced" : "; already replaced: " + replaced));
        }
        releaseSlot(e.slot);
        removeStaged(e.temporary);
        e.temporary.clear();
        replaced += (replaced.empty() ? "" : ", ") + e.path;
        if (afterRename)
            afterRename(++renamed);
    }
    removeJournals();
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
        checkWrittenSize(temporary, text.size(), shown);
    });
}

void checkWrittenSize(const std::string& written, std::uintmax_t bytes, const std::string& shown) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(written, ec);
    if (ec)
        throw InputError(shown + ": writing the file failed: " + ec.message());
    if (size != bytes)
        throw InputError(shown + ": writing the file failed: " + std::to_string(size) + " of " +
                         std::to_string(bytes) +
                         " bytes reached the disk (is it full, or the file over a size limit?)");
}

void recoverInterruptedOutput(const std::string& folder) {
    try {
        std::error_code ec;
        std::vector<fs::path> journals;
        for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
            const std::string name = e.path().filename().string();
            if (isJournalName(name) && processGone(writerPidOf(name)))
                journals.push_back(e.path());
        }
        for (const fs::path& j : journals)
            finishJournal(j);
        const FolderLock lock(folder);
        std::vector<fs::path> stale;
        for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
            const std::string name = e.path().filename().string();
            if (!isJournalName(name) && processGone(writerPidOf(name)) && ownedByMe(e.path()))
                stale.push_back(e.path());
        }
        for (const fs::path& p : stale)
            fs::remove_all(p, ec);
    } catch (const std::exception&) {
        // Best effort: what cannot be read or removed stays as it was.
    }
}

StagedSequence::StagedSequence(const std::string& folder, const std::string& stem,
                               const std::string& ext)
    : m_folder(folder), m_stem(stem), m_ext(ext) {
    recoverOnce(folder);
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
