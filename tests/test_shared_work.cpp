// SharedWork (host/common/shared_work.h), the light tree build's divide-and-conquer
// threads: every element of a loop is visited once, every shared task runs, and an
// exception in a shared task reaches the caller. Broken variants seen to fail: a shared
// half of the loop dropped, and the failure not kept.
#include <atomic>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "common/shared_work.h"

namespace pathcl::test_shared_work {
namespace {

TEST(SharedWork, ForPiecesVisitsEveryElementOnce)
{
    for (unsigned threads : {1u, 2u, 4u}) {
        const std::size_t count = 100003;
        std::vector<std::atomic<int>> visits(count);
        SharedWork::for_pieces(count, 7, threads, [&](std::size_t begin, std::size_t end) {
            ASSERT_LE(end - begin, 7u);
            for (std::size_t i = begin; i < end; ++i)
                visits[i].fetch_add(1, std::memory_order_relaxed);
        });
        std::size_t wrong = 0;
        for (const std::atomic<int>& v : visits)
            wrong += v.load() != 1;
        EXPECT_EQ(wrong, 0u) << threads << " threads";
    }
}

// The sum of [begin, end), halves shared with a waiting thread, the rest summed here.
void shared_sum(SharedWork& work, std::uint64_t begin, std::uint64_t end, std::atomic<std::uint64_t>& total)
{
    while (end - begin > 64) {
        const std::uint64_t mid = begin + (end - begin) / 2;
        if (work.wanted()) {
            work.share([&work, mid, end, &total] { shared_sum(work, mid, end, total); });
            end = mid;
        } else {
            shared_sum(work, mid, end, total);
            end = mid;
        }
    }
    std::uint64_t s = 0;
    for (std::uint64_t i = begin; i < end; ++i)
        s += i;
    total += s;
}

TEST(SharedWork, EverySharedTaskRuns)
{
    for (unsigned threads : {1u, 2u, 4u}) {
        SharedWork work(threads);
        std::atomic<std::uint64_t> total{0};
        const std::uint64_t n = 1u << 20;
        work.run([&] { shared_sum(work, 0, n, total); });
        EXPECT_EQ(total.load(), n * (n - 1) / 2) << threads << " threads";
    }
}

TEST(SharedWork, AnExceptionInASharedTaskReachesTheCaller)
{
    SharedWork work(2);
    std::atomic<int> ran{0};
    EXPECT_THROW(work.run([&] {
        work.share([&] {
            ++ran;
            throw std::runtime_error("shared task");
        });
        ++ran;
    }),
                 std::runtime_error);
    EXPECT_EQ(ran.load(), 2);
}

} // namespace
} // namespace pathcl::test_shared_work
