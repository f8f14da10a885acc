#include "ui/growth_history.hpp"

#include <array>
#include <cassert>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace morphogen::ui {

namespace {

constexpr std::array<char, 8> kMagic = {'M', 'G', 'S', 'T', 'A', 'T', 'E', '1'};

std::size_t stateBytes(const State& s) {
    return s.cellCount() * std::size_t(s.channels()) * sizeof(float);
}

} // namespace

void writeStateFile(const State& state, const std::filesystem::path& file) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    const std::int32_t size[3] = {state.width(), state.height(), state.channels()};
    out.write(kMagic.data(), kMagic.size());
    out.write(reinterpret_cast<const char*>(size), sizeof size);
    for (int c = 0; c < state.channels(); ++c)
        out.write(reinterpret_cast<const char*>(state.plane(c)),
                  std::streamsize(state.cellCount() * sizeof(float)));
    out.close();
    if (!out)
        throw std::runtime_error(file.string() + ": cannot write the history snapshot");
}

State readStateFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::array<char, 8> magic{};
    std::int32_t size[3] = {};
    in.read(magic.data(), magic.size());
    in.read(reinterpret_cast<char*>(size), sizeof size);
    // The designer wrote it in this run; a bad header means the file was
    // changed or cut short under it.
    if (!in || magic != kMagic || size[0] < 1 || size[1] < 1 || size[2] < 1 || size[0] > 65536 ||
        size[1] > 65536 || size[2] > 64)
        throw std::runtime_error(file.string() + ": not a history snapshot (damaged or replaced)");
    State state(size[0], size[1], size[2]);
    for (int c = 0; c < state.channels() && in; ++c)
        in.read(reinterpret_cast<char*>(state.plane(c)),
                std::streamsize(state.cellCount() * sizeof(float)));
    if (!in)
        throw std::runtime_error(file.string() + ": the history snapshot is cut short");
    return state;
}

GrowthHistory::GrowthHistory(std::size_t memoryBudget) : m_memoryBudget(memoryBudget) {}

GrowthHistory::~GrowthHistory() {
    clear();
    std::error_code ignored;
    if (!m_folder.empty())
        std::filesystem::remove(m_folder, ignored); // only if empty: never someone else's files
}

void GrowthHistory::setMemoryBudget(std::size_t bytes) {
    m_memoryBudget = bytes;
    fitBudgets();
}

void GrowthHistory::setSpill(std::filesystem::path folder, std::size_t diskBudget) {
    m_folder = std::move(folder);
    m_diskBudget = diskBudget;
}

void GrowthHistory::record(long long step, RunCheckpoint checkpoint) {
    assert(m_entries.empty() || step > m_entries.back().step);
    m_entries.push_back({step, std::move(checkpoint), {}, 0});
    fitBudgets();
}

std::size_t GrowthHistory::memoryBytes() const {
    std::size_t total = 0;
    for (const Entry& e : m_entries)
        total += stateBytes(e.checkpoint.state);
    return total;
}

void GrowthHistory::fitBudgets() {
    // Spill the oldest states in memory while memory is over budget and the
    // disk has room; the newest stays in memory (it is the one looked at).
    for (std::size_t i = 0; i + 1 < m_entries.size() && memoryBytes() > m_memoryBudget; ++i) {
        Entry& e = m_entries[i];
        if (!e.file.empty())
            continue;
        if (m_folder.empty() || m_diskBytes + stateBytes(e.checkpoint.state) > m_diskBudget ||
            !spill(e))
            break;
    }
    // Then thin the older half until both budgets hold.
    while (m_entries.size() > 2 && (memoryBytes() > m_memoryBudget || m_diskBytes > m_diskBudget)) {
        const std::size_t before = m_entries.size();
        for (std::size_t i = 1; i + 1 < m_entries.size() && i < m_entries.size() / 2; ++i)
            erase(i);
        if (m_entries.size() == before)
            break;
    }
}

bool GrowthHistory::spill(Entry& e) {
    std::error_code error;
    std::filesystem::create_directories(m_folder, error);
    const std::filesystem::path file =
        m_folder / ("snapshot-" + std::to_string(m_nextFile++) + ".state");
    try {
        writeStateFile(e.checkpoint.state, file);
    } catch (const std::runtime_error&) {
        std::filesystem::remove(file, error);
        return false;
    }
    e.fileBytes = stateBytes(e.checkpoint.state);
    m_diskBytes += e.fileBytes;
    e.file = file;
    e.checkpoint.state = State();
    return true;
}

void GrowthHistory::forget(Entry& e) {
    if (e.file.empty())
        return;
    std::error_code ignored;
    std::filesystem::remove(e.file, ignored);
    m_diskBytes -= e.fileBytes;
    e.file.clear();
    e.fileBytes = 0;
}

void GrowthHistory::erase(std::size_t i) {
    forget(m_entries[i]);
    m_entries.erase(m_entries.begin() + std::ptrdiff_t(i));
    m_cachedIndex = std::size_t(-1);
}

const State& GrowthHistory::state(std::size_t i) const {
    const Entry& e = m_entries.at(i);
    if (e.file.empty())
        return e.checkpoint.state;
    if (m_cachedIndex != i) {
        m_cached = readStateFile(e.file);
        m_cachedIndex = i;
    }
    return m_cached;
}

RunCheckpoint GrowthHistory::checkpoint(std::size_t i) const {
    RunCheckpoint c = m_entries.at(i).checkpoint;
    if (!m_entries[i].file.empty())
        c.state = state(i);
    return c;
}

void GrowthHistory::keepUpTo(std::size_t i) {
    while (m_entries.size() > i + 1)
        erase(m_entries.size() - 1);
}

void GrowthHistory::dropAfterStep(long long step) {
    while (!m_entries.empty() && m_entries.back().step > step)
        erase(m_entries.size() - 1);
}

void GrowthHistory::clear() {
    while (!m_entries.empty())
        erase(m_entries.size() - 1);
}

} // namespace morphogen::ui
