#include "cli/interrupt.h"

#include <csignal>

#include "common/staged_files.h"

namespace pathcl::cli {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int sig)
{
    if (g_signal != 0) {
        // The second one ends the process at once, without the outputs being written: the
        // temporary files go, every existing output stays as it was.
        remove_staged_files_on_signal();
        std::signal(sig, SIG_DFL);
        std::raise(sig);
        return;
    }
    g_signal = sig;
}

} // namespace

void catch_interrupts()
{
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
}

bool interrupted()
{
    return g_signal != 0;
}

int interrupt_signal()
{
    return g_signal;
}

int interrupted_exit_code()
{
    return 128 + g_signal;
}

} // namespace pathcl::cli
