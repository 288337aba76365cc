#include "cli/interrupt.h"

#include <csignal>

namespace pathcl::cli {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int sig)
{
    g_signal = sig;
    // The next one is not caught: a second Ctrl-C ends the process at once.
    std::signal(sig, SIG_DFL);
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
