#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include <candela/ecs/job_system.h>

namespace candela::ecs {
namespace {

TEST(JobSystem, ParallelForVisitsEveryIndexOnce) {
    JobSystem jobs(3);
    std::vector<std::atomic<int>> hits(10'000);
    jobs.parallelFor(hits.size(), 64, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            hits[i].fetch_add(1, std::memory_order_relaxed);
    });
    for (const auto& h : hits)
        ASSERT_EQ(h.load(), 1);
}

TEST(JobSystem, WorksWithoutWorkers) {
    JobSystem jobs(0);
    EXPECT_EQ(jobs.threadCount(), 1u);
    int sum = 0;
    JobSystem::WaitGroup group;
    for (int i = 1; i <= 10; ++i)
        jobs.run(group, [&sum, i] { sum += i; });
    jobs.wait(group);
    EXPECT_EQ(sum, 55);
}

TEST(JobSystem, NestedParallelismDoesNotDeadlock) {
    JobSystem jobs(2);
    std::atomic<int> total{0};
    jobs.parallelFor(8, 1, [&](std::size_t, std::size_t) {
        jobs.parallelFor(100, 10, [&](std::size_t begin, std::size_t end) {
            total.fetch_add(static_cast<int>(end - begin), std::memory_order_relaxed);
        });
    });
    EXPECT_EQ(total.load(), 800);
}

TEST(JobSystem, ExceptionsReachTheWaiter) {
    JobSystem jobs(2);
    JobSystem::WaitGroup group;
    std::atomic<int> ran{0};
    for (int i = 0; i < 10; ++i) {
        jobs.run(group, [&, i] {
            ran.fetch_add(1);
            if (i == 3) throw std::runtime_error("job 3 failed");
        });
    }
    EXPECT_THROW(jobs.wait(group), std::runtime_error);
    EXPECT_EQ(ran.load(), 10);  // the other jobs still ran
}

TEST(JobSystem, ThreadIndicesAreDistinct) {
    JobSystem jobs(2);
    EXPECT_EQ(jobs.threadIndex(), 0u);  // not a worker
    std::vector<std::atomic<int>> seen(jobs.threadCount());
    jobs.parallelFor(1000, 1, [&](std::size_t, std::size_t) {
        const unsigned index = jobs.threadIndex();
        ASSERT_LT(index, jobs.threadCount());
        seen[index].fetch_add(1, std::memory_order_relaxed);
    });
    int total = 0;
    for (const auto& s : seen)
        total += s.load();
    EXPECT_EQ(total, 1000);
}

}  // namespace
}  // namespace candela::ecs
