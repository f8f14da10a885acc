#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace morphogen {

// A barrier for the threads of one parallel region that spins while the
// wait is short and sleeps once it is not.
//
// Why not `omp barrier`: libgomp spins GOMP_SPINCOUNT times before it puts
// a thread to sleep, and the designer sets that low (3,000) so that idle
// OpenMP threads leave the cores to the software rasterizer between frames.
// Inside a batch of steps that made a thread sleep and be woken again on
// ~5% of the steps (perf sched: 17 sleeps a frame of 330 steps), a core idle
// each time. The bands of one step end microseconds apart, so spinning
// through them costs nothing; after kSpins a waiter sleeps on a condition
// variable, so a thread whose partner lost its core (more threads than
// cores: an export beside the designer's run) does not burn that core.
class SpinBarrier {
public:
    explicit SpinBarrier(int threads) : m_threads(threads) {}
    SpinBarrier(const SpinBarrier&) = delete;
    SpinBarrier& operator=(const SpinBarrier&) = delete;

    void wait() {
        const unsigned generation = m_generation.load();
        if (m_arrived.fetch_add(1) + 1 == m_threads) {
            // The last to arrive: the next barrier's count starts before
            // anyone can see this one open.
            m_arrived.store(0);
            m_generation.store(generation + 1);
            // Sequentially consistent with the sleeper's count-then-check
            // below: either it sees the new generation or this sees it.
            if (m_sleepers.load() > 0) {
                std::lock_guard<std::mutex> lock(m_mutex);
                m_open.notify_all();
            }
            return;
        }
        for (int spins = 0; spins < kSpins; ++spins) {
            if (m_generation.load(std::memory_order_acquire) != generation)
                return;
            relax();
        }
        std::unique_lock<std::mutex> lock(m_mutex);
        ++m_sleepers;
        m_open.wait(lock, [&] { return m_generation.load() != generation; });
        --m_sleepers;
    }

    // About 50-200 microseconds of pauses, depending on the CPU.
    static constexpr int kSpins = 4000;

private:
    static void relax() {
#if defined(__x86_64__) || defined(__i386__)
        _mm_pause();
#endif
    }

    const int m_threads;
    std::atomic<int> m_arrived{0};
    std::atomic<unsigned> m_generation{0};
    std::atomic<int> m_sleepers{0};
    std::mutex m_mutex;
    std::condition_variable m_open;
};

} // namespace morphogen
