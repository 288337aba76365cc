// Recursive work on every core, for a divide-and-conquer build whose pieces differ in size
// (the light tree's subtrees): a task hands a piece of its work to another thread only
// while one is waiting for work, so that no thread idles while another still has a
// large piece, and no piece is split off that a busy thread would rather do itself. Its
// threads are its own and sleep while they wait: OpenImageIO's thread pool, which the
// film's loops once ran on, keeps its threads spinning for a while after a loop, which
// slowed a light tree built next to it from 0.65 to 1.1 s on a 2-core machine.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <vector>

namespace pathcl {

class SharedWork {
public:
    // At most `threads` threads (the caller's among them; 0: one a core).
    explicit SharedWork(unsigned threads = 0);

    // Runs `first` and every task it (or a task after it) shares, and returns when all
    // have run; rethrows the first exception one threw.
    void run(const std::function<void()>& first);

    // Whether a thread is waiting for a task to share with it.
    bool wanted() const { return waiting_.load(std::memory_order_relaxed) > queued_.load(std::memory_order_relaxed); }

    // Hands `task` to a waiting thread (or, if none takes it first, to the next thread
    // that finishes its task).
    void share(std::function<void()> task);

    // Calls fn(begin, end) on consecutive pieces of at most `piece` elements that cover
    // [0, count), on `threads` threads (0: one a core): a loop whose elements are
    // independent.
    static void for_pieces(std::size_t count, std::size_t piece, unsigned threads,
                           const std::function<void(std::size_t begin, std::size_t end)>& fn);

private:
    void work();

    unsigned threads_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::vector<std::function<void()>> tasks_;
    std::atomic<int> waiting_{0}, queued_{0};
    int busy_ = 0;
    std::exception_ptr failure_;
};

} // namespace pathcl
