// Puts a dynamic TLS block 16 bytes into a page and exits while its thread lives, so that
// LeakSanitizer's check at exit scans it. GCC 12's runtime takes such a block for glibc
// 2.18's layout and reads its bounds from the allocator's header before it; its tracer
// then crashes ("Tracer caught signal 11") unless the program's default options turn the
// interception off (host/common/sanitizer_options.cpp, linked in). Exit code 0: the check
// ran; 77: no block landed there (another allocator or libc), nothing was shown.
//
//   tls_probe LIBRARY.so
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

#include <dlfcn.h>

namespace {

using Touch = char* (*)();

// Every allocation stays reachable, so that the check has nothing to report.
void* volatile kept[1 << 14];
int kept_count = 0;

std::mutex mutex;
std::condition_variable changed;
int outcome = 0; // 1: the block landed 16 bytes into a page; -1: elsewhere

void probe(Touch touch)
{
    // Chunks of the block's size class (64 bytes apart in AddressSanitizer's allocator),
    // one after the other, until the next one starts 16 bytes into a page; then the first
    // touch allocates the block there.
    for (int i = 0; i < 200 && kept_count < (1 << 14); ++i) {
        void* chunk = std::malloc(40);
        kept[kept_count++] = chunk;
        if ((reinterpret_cast<std::uintptr_t>(chunk) + 64) % 4096 == 16)
            break;
    }
    const bool landed = reinterpret_cast<std::uintptr_t>(touch()) % 4096 == 16;
    {
        const std::lock_guard<std::mutex> lock(mutex);
        outcome = landed ? 1 : -1;
    }
    changed.notify_one();
    if (landed)
        for (;;) // alive through the check at exit
            std::this_thread::sleep_for(std::chrono::hours(1));
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: tls_probe LIBRARY.so\n");
        return 2;
    }
    void* library = dlopen(argv[1], RTLD_NOW);
    if (!library) {
        std::fprintf(stderr, "tls_probe: %s\n", dlerror());
        return 2;
    }
    const auto touch = reinterpret_cast<Touch>(dlsym(library, "tls_probe_touch"));
    if (!touch) {
        std::fprintf(stderr, "tls_probe: %s has no tls_probe_touch\n", argv[1]);
        return 2;
    }
    for (int attempt = 0; attempt < 20; ++attempt) {
        outcome = 0;
        std::thread thread(probe, touch);
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait(lock, [] { return outcome != 0; });
        lock.unlock();
        if (outcome == 1) {
            std::printf("tls_probe: a dynamic TLS block 16 bytes into a page, attempt %d\n", attempt);
            thread.detach();
            return 0;
        }
        thread.join();
    }
    std::printf("tls_probe: no dynamic TLS block landed 16 bytes into a page\n");
    return 77;
}
