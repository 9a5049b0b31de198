#pragma once
// A small job system: a fixed set of worker threads sharing one queue. Whoever waits for a
// group of jobs helps run queued jobs meanwhile, so nested parallelism cannot deadlock and the
// calling thread is never idle. Meant for frame-sized work (systems, chunks of a view), not
// for tiny tasks: each job costs a lock and a std::function.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace candela::ecs {

class JobSystem {
public:
    // Jobs added with run() count against a WaitGroup; wait() returns when all are done and
    // rethrows the first exception a job threw.
    class WaitGroup {
    public:
        WaitGroup() = default;
        WaitGroup(const WaitGroup&) = delete;
        WaitGroup& operator=(const WaitGroup&) = delete;

    private:
        friend class JobSystem;
        std::size_t pending_ = 0;  // guarded by the job system's mutex
        std::exception_ptr error_;
    };

    // workerThreads = 0 runs everything on the thread that waits.
    explicit JobSystem(unsigned workerThreads = defaultWorkerCount());
    ~JobSystem();
    JobSystem(const JobSystem&) = delete;
    JobSystem& operator=(const JobSystem&) = delete;

    // One worker per hardware thread beyond the caller's.
    static unsigned defaultWorkerCount();

    unsigned workerCount() const noexcept { return static_cast<unsigned>(workers_.size()); }
    // Threads that may run jobs: the workers plus the waiting thread.
    unsigned threadCount() const noexcept { return workerCount() + 1; }
    // 1..workerCount() on this system's workers, 0 on any other thread. Lets callers keep
    // per-thread data (command buffers) in an array of threadCount() entries.
    unsigned threadIndex() const noexcept;

    void run(WaitGroup& group, std::function<void()> job);
    void wait(WaitGroup& group);

    // Calls fn(begin, end) over [0, count) in slices of about `grain`, in parallel, and waits.
    template <class F>
    void parallelFor(std::size_t count, std::size_t grain, F&& fn) {
        if (count == 0) return;
        if (grain == 0) grain = 1;
        if (count <= grain || workers_.empty()) {
            fn(std::size_t{0}, count);
            return;
        }
        WaitGroup group;
        for (std::size_t begin = 0; begin < count; begin += grain) {
            const std::size_t end = count - begin < grain ? count : begin + grain;
            run(group, [&fn, begin, end] { fn(begin, end); });
        }
        wait(group);
    }

private:
    struct Job {
        std::function<void()> fn;
        WaitGroup* group;
    };
    void workerLoop(unsigned index);
    // Runs one job (the lock is released while it runs). Returns with the lock held.
    void execute(std::unique_lock<std::mutex>& lock, Job job);

    std::mutex mutex_;
    std::condition_variable workAvailable_;
    std::condition_variable stateChanged_;  // a job was queued or a group finished
    std::deque<Job> queue_;
    bool stopping_ = false;
    std::vector<std::thread> workers_;
};

}  // namespace candela::ecs
