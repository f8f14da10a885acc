#pragma once

#include <atomic>
#include <thread>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace morphogen {

// A barrier for the threads of one parallel region that spins while the
// wait is short and yields the core once it is not.
//
// Why not `omp barrier`: libgomp spins GOMP_SPINCOUNT times before it puts
// a thread to sleep, and the designer sets that low (3,000) so that idle
// OpenMP threads leave the cores to the software rasterizer between frames.
// Inside a batch of steps that made a thread sleep and be woken again on
// ~5% of the steps (perf sched: 17 sleeps a frame of 330 steps), a core idle
// each time. The bands of one step end microseconds apart, so spinning
// through them costs nothing; yielding after kSpins keeps a thread whose
// partner lost its core (more threads than cores) from burning that core.
class SpinBarrier {
public:
    explicit SpinBarrier(int threads) : m_threads(threads) {}
    SpinBarrier(const SpinBarrier&) = delete;
    SpinBarrier& operator=(const SpinBarrier&) = delete;

    void wait() {
        const unsigned generation = m_generation.load(std::memory_order_acquire);
        if (m_arrived.fetch_add(1, std::memory_order_acq_rel) + 1 == m_threads) {
            // The last to arrive: the next barrier's count starts before
            // anyone can see this one open.
            m_arrived.store(0, std::memory_order_relaxed);
            m_generation.store(generation + 1, std::memory_order_release);
            return;
        }
        for (int spins = 0; m_generation.load(std::memory_order_acquire) == generation; ++spins) {
            if (spins < kSpins)
                relax();
            else
                std::this_thread::yield();
        }
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
};

} // namespace morphogen
