#include <candela/ecs/job_system.h>

namespace candela::ecs {
namespace {

// Which job system (if any) the current thread works for, and its index there.
thread_local const JobSystem* tlsOwner = nullptr;
thread_local unsigned tlsIndex = 0;

}  // namespace

unsigned JobSystem::defaultWorkerCount() {
    const unsigned hardware = std::thread::hardware_concurrency();
    return hardware > 1 ? hardware - 1 : 0;
}

JobSystem::JobSystem(unsigned workerThreads) {
    workers_.reserve(workerThreads);
    for (unsigned i = 0; i < workerThreads; ++i) {
        workers_.emplace_back([this, i] { workerLoop(i + 1); });
    }
}

JobSystem::~JobSystem() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    workAvailable_.notify_all();
    for (std::thread& worker : workers_)
        worker.join();
}

unsigned JobSystem::threadIndex() const noexcept {
    return tlsOwner == this ? tlsIndex : 0;
}

void JobSystem::run(WaitGroup& group, std::function<void()> job) {
    {
        const std::lock_guard lock(mutex_);
        ++group.pending_;
        queue_.push_back(Job{std::move(job), &group});
    }
    workAvailable_.notify_one();
    stateChanged_.notify_all();  // waiters wake up to help with it
}

void JobSystem::execute(std::unique_lock<std::mutex>& lock, Job job) {
    lock.unlock();
    std::exception_ptr error;
    try {
        job.fn();
    } catch (...) {
        error = std::current_exception();
    }
    job.fn = nullptr;  // release captures outside the lock
    lock.lock();
    if (error && !job.group->error_) job.group->error_ = error;
    if (--job.group->pending_ == 0) stateChanged_.notify_all();
}

void JobSystem::wait(WaitGroup& group) {
    std::unique_lock lock(mutex_);
    while (group.pending_ > 0) {
        if (!queue_.empty()) {
            // Help instead of sleeping (any job: ours may be waiting behind it).
            Job job = std::move(queue_.front());
            queue_.pop_front();
            execute(lock, std::move(job));
        } else {
            stateChanged_.wait(lock);
        }
    }
    if (group.error_) {
        std::exception_ptr error = group.error_;
        group.error_ = nullptr;
        std::rethrow_exception(error);
    }
}

void JobSystem::workerLoop(unsigned index) {
    tlsOwner = this;
    tlsIndex = index;
    std::unique_lock lock(mutex_);
    while (true) {
        workAvailable_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
        if (queue_.empty()) return;  // stopping and drained
        Job job = std::move(queue_.front());
        queue_.pop_front();
        execute(lock, std::move(job));
    }
}

}  // namespace candela::ecs
