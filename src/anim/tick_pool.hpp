// The worker threads of a parallel tick: started once; between ticks each stays awake for a
// while (ticks often come back to back: sub-steps, several engines, benchmarks) and then
// sleeps on a condition variable. Ticks once a frame find their workers awake too: the
// pool times the jobs that open after a gap (a frame's first tick), and a sleeping worker
// wakes by itself `awake` before the next one is due and waits for it awake, up to `awake`
// past the time it was due.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace grape::detail {

class TickPool {
public:
    using Job = void (*)(void* context) noexcept;

    /// Starts `workers` threads (may throw std::system_error). After each job a worker waits
    /// awake for the next one up to `awake`, then sleeps (until the next job, or until
    /// `awake` before the next job after a gap is due: see the class).
    TickPool(int workers, std::chrono::nanoseconds awake);
    /// Stops and joins the workers.
    ~TickPool();
    TickPool(const TickPool&) = delete;
    TickPool& operator=(const TickPool&) = delete;

    /// Calls job(context) on the calling thread and on every worker that joins while the
    /// calling thread's call runs; returns once every call has returned. The job shares its
    /// work through the context (each call takes pieces until none are left), so a worker the
    /// system schedules late is not waited for: it finds the job closed and waits again.
    void run(Job job, void* context) noexcept;

    int workers() const noexcept { return static_cast<int>(threads_.size()); }
    std::chrono::nanoseconds awake() const noexcept { return awake_; }

private:
    void work() noexcept;
    // Sets stop_, wakes every sleeper and joins every thread started so far.
    void stop_and_join() noexcept;
    // The next open job after `seen`, waiting awake and then asleep; false on stop.
    bool wait_for_job(std::uint64_t seen) noexcept;
    // Waits awake until `ready` or `until`; whether ready.
    template <class Ready>
    static bool spin_until(Ready&& ready, std::chrono::steady_clock::time_point until) noexcept;

    // state_ = 2 · jobs run so far, plus 1 while the next one is open. job_ and context_ are
    // written before a job opens (release) and read by a worker only after it has counted
    // itself in active_ and seen the same open state again: run() does not return, so does
    // not write them again, while a worker that saw them open is counted.
    std::atomic<std::uint64_t> state_{0};
    std::atomic<int> active_{0};    // workers counted into the current job
    std::atomic<int> sleepers_{0};  // workers asleep on start_, or about to be
    std::atomic<bool> stop_{false};
    // When the next job after a gap is due, as steady_clock's count (0: not known); written by
    // the calling thread only. A gap: longer than `awake` since the previous job closed.
    std::atomic<std::int64_t> due_{0};
    std::chrono::steady_clock::time_point last_closed_{}, last_gap_open_{};
    Job job_ = nullptr;
    void* context_ = nullptr;
    std::chrono::nanoseconds awake_;
    std::mutex mutex_;               // guards start_'s sleep, not the job
    std::condition_variable start_;  // a job was opened, or stop
    std::vector<std::thread> threads_;
};

}  // namespace grape::detail
