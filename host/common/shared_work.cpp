#include "common/shared_work.h"

#include <algorithm>
#include <thread>

namespace pathcl {

SharedWork::SharedWork(unsigned threads)
    : threads_(threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency()))
{}

void SharedWork::run(const std::function<void()>& first)
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        tasks_.push_back(first);
        queued_ = 1;
        busy_ = 0;
        failure_ = nullptr;
    }
    std::vector<std::thread> helpers;
    try {
        for (unsigned i = 1; i < threads_; ++i)
            helpers.emplace_back([this] { work(); });
    } catch (...) {
        // Fewer threads than asked for: the work still gets done, on those there are.
    }
    work();
    for (std::thread& t : helpers)
        t.join();
    if (failure_)
        std::rethrow_exception(failure_);
}

void SharedWork::share(std::function<void()> task)
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        tasks_.push_back(std::move(task));
        ++queued_;
    }
    wake_.notify_one();
}

void SharedWork::work()
{
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        if (!tasks_.empty()) {
            std::function<void()> task = std::move(tasks_.back());
            tasks_.pop_back();
            --queued_;
            ++busy_;
            lock.unlock();
            try {
                task();
            } catch (...) {
                lock.lock();
                if (!failure_)
                    failure_ = std::current_exception();
                lock.unlock();
            }
            lock.lock();
            --busy_;
            if (busy_ == 0 && tasks_.empty())
                wake_.notify_all(); // nothing left to share: the waiting threads are done
            continue;
        }
        if (busy_ == 0)
            return;
        ++waiting_;
        wake_.wait(lock, [this] { return !tasks_.empty() || busy_ == 0; });
        --waiting_;
    }
}

namespace {

// fn over [begin, end), `piece` elements at a time, sharing half of what is left whenever
// a thread waits for work.
void pieces(SharedWork& work, std::size_t begin, std::size_t end, std::size_t piece,
            const std::function<void(std::size_t, std::size_t)>& fn)
{
    while (begin < end) {
        if (end - begin > 2 * piece && work.wanted()) {
            const std::size_t mid = begin + (end - begin) / 2;
            work.share([&work, mid, end, piece, &fn] { pieces(work, mid, end, piece, fn); });
            end = mid;
        }
        const std::size_t stop = std::min(end, begin + piece);
        fn(begin, stop);
        begin = stop;
    }
}

} // namespace

void SharedWork::for_pieces(std::size_t count, std::size_t piece, unsigned threads,
                            const std::function<void(std::size_t, std::size_t)>& fn)
{
    SharedWork work(threads);
    work.run([&] { pieces(work, 0, count, std::max<std::size_t>(1, piece), fn); });
}

} // namespace pathcl
