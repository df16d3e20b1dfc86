// The worker threads of a parallel tick: one mutex, two condition variables, no allocation
// after construction.
#include "tick_pool.hpp"

namespace grape::detail {

TickPool::TickPool(int workers) {
    threads_.reserve(static_cast<std::size_t>(workers));
    try {
        for (int k = 0; k < workers; ++k) threads_.emplace_back([this] { work(); });
    } catch (...) {
        {
            const std::lock_guard lock(mutex_);
            stop_ = true;
        }
        start_.notify_all();
        for (std::thread& t : threads_) t.join();
        throw;
    }
}

TickPool::~TickPool() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    start_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void TickPool::run(Job job, void* context) noexcept {
    {
        const std::lock_guard lock(mutex_);
        job_ = job;
        context_ = context;
        ++epoch_;
    }
    start_.notify_all();
    job(context);
    std::unique_lock lock(mutex_);
    job_ = nullptr;  // no worker enters from now on
    done_.wait(lock, [this] { return active_ == 0; });
}

void TickPool::work() noexcept {
    std::uint64_t seen = 0;
    std::unique_lock lock(mutex_);
    for (;;) {
        start_.wait(lock, [&] { return stop_ || (job_ && epoch_ != seen); });
        if (stop_) return;
        seen = epoch_;
        const Job job = job_;
        void* const context = context_;
        ++active_;
        lock.unlock();
        job(context);
        lock.lock();
        if (--active_ == 0) done_.notify_all();
    }
}

}  // namespace grape::detail
