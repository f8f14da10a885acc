// SpinBarrier: no thread passes it before every thread has arrived, round
// after round, also with more threads than cores (the yielding path).

#include <atomic>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/sim/spin_barrier.hpp"

using morphogen::SpinBarrier;

namespace {

// Each round every thread writes its slot, meets the others, checks that
// every slot holds this round, and meets them again before the next writes.
int roundsSeenWrong(int threads, int rounds) {
    SpinBarrier barrier(threads);
    std::vector<std::atomic<int>> slots(static_cast<std::size_t>(threads));
    std::atomic<int> wrong{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            for (int r = 0; r < rounds; ++r) {
                slots[std::size_t(t)].store(r, std::memory_order_relaxed);
                barrier.wait();
                for (const std::atomic<int>& s : slots)
                    wrong += s.load(std::memory_order_relaxed) != r;
                barrier.wait();
            }
        });
    for (std::thread& t : pool)
        t.join();
    return wrong;
}

} // namespace

TEST(SpinBarrier, NoThreadPassesBeforeAllArrive) {
    EXPECT_EQ(roundsSeenWrong(2, 20000), 0);
    EXPECT_EQ(roundsSeenWrong(3, 5000), 0);
}

TEST(SpinBarrier, MoreThreadsThanCoresStillGetThrough) {
    const int threads = 4 * int(std::max(1u, std::thread::hardware_concurrency()));
    EXPECT_EQ(roundsSeenWrong(threads, 300), 0);
}
