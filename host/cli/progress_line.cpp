#include "cli/progress_line.h"

#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace pathcl::cli {

ProgressLine::ProgressLine(Mode mode, std::string label) : label_(std::move(label))
{
    if (mode == Mode::Quiet)
        return;
    tty_ = isatty(STDERR_FILENO) != 0;
    lines_ = !tty_ && mode == Mode::Lines;
}

ProgressLine::~ProgressLine()
{
    finish();
}

std::string format_duration(double s)
{
    char buf[48];
    if (!std::isfinite(s) || s < 0.0)
        return "?";
    if (s < 60.0)
        std::snprintf(buf, sizeof buf, "%.1f s", s);
    else if (s < 3600.0)
        std::snprintf(buf, sizeof buf, "%d min %02d s", static_cast<int>(s / 60.0),
                      static_cast<int>(std::fmod(s, 60.0)));
    else
        std::snprintf(buf, sizeof buf, "%d h %02d min", static_cast<int>(s / 3600.0),
                      static_cast<int>(std::fmod(s, 3600.0) / 60.0));
    return buf;
}

void ProgressLine::show(const RenderProgress& p, const std::string& label)
{
    if (!tty_ && !lines_)
        return;
    const double period = tty_ ? 0.25 : 5.0;
    if (last_ >= 0.0 && p.elapsed_seconds - last_ < period && p.spp < p.max_spp)
        return;
    last_ = p.elapsed_seconds;
    std::string error = p.error_estimate >= 0.0 ? "" : "-";
    if (p.error_estimate >= 0.0) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.3g", p.error_estimate);
        error = buf;
    }
    char line[512];
    std::snprintf(line, sizeof line, "%s: pass %u/%u | %.3g samples/s | %s elapsed | ETA %s | relMSE est. %s",
                  label.c_str(), p.spp, p.max_spp, p.samples_per_second, format_duration(p.elapsed_seconds).c_str(),
                  format_duration(p.eta_seconds).c_str(), error.c_str());
    if (tty_) {
        std::fprintf(stderr, "\r\033[K%s", line);
        drawn_ = true;
    } else {
        std::fprintf(stderr, "%s\n", line);
    }
    std::fflush(stderr);
}

void ProgressLine::finish()
{
    if (drawn_) {
        std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
        drawn_ = false;
    }
}

} // namespace pathcl::cli
