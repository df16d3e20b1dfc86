// The worker threads of a parallel tick: started once, asleep between ticks.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace grape::detail {

class TickPool {
public:
    using Job = void (*)(void* context) noexcept;

    /// Starts `workers` threads (may throw std::system_error).
    explicit TickPool(int workers);
    /// Stops and joins the workers.
    ~TickPool();
    TickPool(const TickPool&) = delete;
    TickPool& operator=(const TickPool&) = delete;

    /// Calls job(context) on the calling thread and on every worker that wakes while the
    /// calling thread's call runs; returns once every call has returned. The job shares its
    /// work through the context (each call takes pieces until none are left), so a worker the
    /// system schedules late is not waited for: it finds the job closed and sleeps again.
    void run(Job job, void* context) noexcept;

    int workers() const noexcept { return static_cast<int>(threads_.size()); }

private:
    void work() noexcept;

    std::mutex mutex_;
    std::condition_variable start_;  // a job was opened, or stop
    std::condition_variable done_;   // the last active worker left the job
    Job job_ = nullptr;              // the open job (null: closed)
    void* context_ = nullptr;
    std::uint64_t epoch_ = 0;        // jobs opened so far; a worker joins each one at most once
    int active_ = 0;                 // workers inside job_ now
    bool stop_ = false;
    std::vector<std::thread> threads_;
};

}  // namespace grape::detail
