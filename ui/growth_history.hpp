#pragma once

#include <cstddef>
#include <deque>
#include <filesystem>
#include <string>

#include "core/sim/session_run.hpp"

namespace morphogen::ui {

// The designer's growth history: checkpoints of the run taken as the pattern
// grows, for the timeline to look back along and branch from. GL-free.
//
// States are kept in memory up to a budget; past it, the oldest in memory go
// to files in a spill folder (when one is set) up to a disk budget, and past
// that the older half of the timeline is thinned (every other snapshot
// goes), so the timeline keeps its whole span, coarser towards the start. A
// spilled state is read back when it is looked at. The files are removed
// when their snapshots go and when the history is destroyed.
class GrowthHistory {
public:
    explicit GrowthHistory(std::size_t memoryBudget = std::size_t(256) << 20);
    ~GrowthHistory();
    GrowthHistory(const GrowthHistory&) = delete;
    GrowthHistory& operator=(const GrowthHistory&) = delete;

    void setMemoryBudget(std::size_t bytes);
    // A folder for spilled states (created when first needed; empty: keep
    // everything in memory) and how many bytes of it to use.
    void setSpill(std::filesystem::path folder, std::size_t diskBudget);

    // A checkpoint at session step `step` (later than the last one).
    void record(long long step, RunCheckpoint checkpoint);

    std::size_t size() const { return m_entries.size(); }
    bool empty() const { return m_entries.empty(); }
    long long step(std::size_t i) const { return m_entries[i].step; }
    long long lastStep() const { return m_entries.back().step; }
    bool spilled(std::size_t i) const { return !m_entries[i].file.empty(); }
    // Snapshot i's state (read back from its file if spilled; the last one
    // read is cached). Throws std::runtime_error when the file cannot be read.
    const State& state(std::size_t i) const;
    // Snapshot i's checkpoint with its state.
    RunCheckpoint checkpoint(std::size_t i) const;

    // Drops the snapshots after index i / after session step `step`.
    void keepUpTo(std::size_t i);
    void dropAfterStep(long long step);
    void clear();

    std::size_t memoryBytes() const;
    std::size_t diskBytes() const { return m_diskBytes; }

private:
    struct Entry {
        long long step = 0;
        RunCheckpoint checkpoint; // its state empty when spilled
        std::filesystem::path file;
        std::size_t fileBytes = 0;
    };
    void fitBudgets();
    // Writes entry e's state to a file and frees it; false when that fails
    // (a full disk: the history thins instead).
    bool spill(Entry& e);
    void forget(Entry& e);
    void erase(std::size_t i);

    std::deque<Entry> m_entries;
    std::size_t m_memoryBudget;
    std::filesystem::path m_folder;
    std::size_t m_diskBudget = 0;
    std::size_t m_diskBytes = 0;
    std::size_t m_nextFile = 0;
    mutable std::size_t m_cachedIndex = std::size_t(-1);
    mutable State m_cached;
};

// Writes and reads a state as a raw file (a small header, then the planes);
// throws std::runtime_error naming the file.
void writeStateFile(const State& state, const std::filesystem::path& file);
State readStateFile(const std::filesystem::path& file);

} // namespace morphogen::ui
