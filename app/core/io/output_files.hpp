#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace morphogen {

// Output safety: a file the program writes appears at its path complete or
// not at all, and a run that fails leaves the previous files there untouched.
// Every file is written to a temporary in the same folder (a rename within a
// folder is atomic) and renamed into place once everything it belongs with is
// written. Temporaries are removed when a write fails (exception) and, through
// removeTemporariesForSignal, when a fatal signal ends the process.

// The temporary `path` is written to: the same folder, a hidden name holding
// the process id and a counter (two runs, or two files, never share one) and
// ending in the path's extension, which image writers pick the format by:
// "dir/.~name.1234-0.png". The name is cut to fit the file system's 255 bytes.
std::string temporaryPathFor(const std::string& path);

// Files that replace their previous versions together or not at all, e.g. a
// render's image and the session that reproduces it.
class OutputFiles {
public:
    OutputFiles() = default;
    // Uncommitted (a write failed, an exception is on its way): removes every
    // temporary, so nothing at the output paths changed.
    ~OutputFiles();
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;

    // The temporary to write `path` to. The writers (writeFileAtomically and
    // everything built on it) write a staged temporary in place, so
    // `writeImageRows(files.stage(p), ...)` adds the image to this set.
    std::string stage(const std::string& path);

    // Renames every staged file into place, in the order staged (callers
    // stage the session last: it is the record of what the other files
    // show). Before the first rename, every temporary must exist and no final
    // path may be a folder, so the likely failures change nothing; a rename
    // that still fails throws naming the files already replaced, and the
    // remaining temporaries are removed.
    //
    // The set is replaced as one: the folders it writes to are locked
    // (flock) while it renames, so two runs to the same paths cannot
    // interleave their files, and a set of several files is listed in a
    // journal first, so a run killed between two renames has its commit
    // finished by the next run to the folder (recoverInterruptedOutput).
    // `afterRename` (tests) is called after each rename with the count so far.
    void commit(const std::function<void(int renamed)>& afterRename = {});

    // The final paths, in order.
    std::vector<std::string> paths() const;

private:
    struct Entry {
        std::string path, temporary;
        int slot; // in the signal-time registry; -1: not registered
    };
    std::vector<Entry> m_entries;
    bool m_done = false;
};

// Writes one file safely: `write` fills the temporary it is given, which then
// replaces `path`; an exception from `write` removes the temporary and
// propagates. A `path` that is an OutputFiles temporary is written in place,
// its set renames it.
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& temporary)>& write);

// The final path of an OutputFiles temporary, else `path`: what messages name.
std::string finalPathOf(const std::string& path);

// `text` as the file `path`, atomically; throws InputError naming the path
// when it cannot be written.
void writeTextAtomically(const std::string& path, const std::string& text);

// A numbered series of files (frame_00000.png, ...) bound for `folder`:
// written meanwhile into a private folder inside it, and moved in together by
// commit(), which first removes the series already there (files named stem,
// five or more digits, ext). Until then the previous series stays; destroyed
// uncommitted, or on a fatal signal, it removes its files and folder.
class StagedSequence {
public:
    StagedSequence(const std::string& folder, const std::string& stem, const std::string& ext);
    ~StagedSequence();
    StagedSequence(const StagedSequence&) = delete;
    StagedSequence& operator=(const StagedSequence&) = delete;

    // Where file `index` (from 0, in order) is written before commit().
    std::string path(int index) const;
    // Its final path.
    std::string finalPath(int index) const;
    // File `index` is complete: it is moved at commit(), removed on failure.
    void written(int index);
    // Replaces the folder's series with the files written (commit of none
    // still removes the old series: the run made none).
    void commit();
    int count() const { return m_count; }

private:
    std::string name(int index) const;
    std::string m_folder, m_stem, m_ext, m_staging;
    int m_count = 0;
    int m_slot = -1;
    bool m_done = false;
};

// What a killed run left in `folder` (its process no longer runs): a commit
// it had begun is finished from its journal (every file in it was complete
// before the first rename), then its temporaries and staged series are
// removed. Never throws; files it cannot touch stay. OutputFiles::stage and
// StagedSequence call it once per folder per process, so the next run to a
// folder cleans up after a killed one.
void recoverInterruptedOutput(const std::string& folder);

// Throws InputError naming `shown` unless the file `written` holds exactly
// `bytes` bytes: a writer that does not report short writes (a full disk,
// the file-size limit) is caught before its file replaces a good one.
void checkWrittenSize(const std::string& written, std::uintmax_t bytes, const std::string& shown);

// Removes every live temporary and staged series. Async-signal-safe (unlink
// and rmdir only): for a handler of SIGINT, SIGTERM or SIGHUP that then ends
// the process.
void removeTemporariesForSignal();

// How many temporaries and staged series are live (tests).
int liveTemporaryCount();

} // namespace morphogen
