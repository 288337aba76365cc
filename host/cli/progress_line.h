// Render progress on stderr: on a terminal one self-updating line (passes done / planned,
// samples per second, elapsed, ETA, estimated error), redrawn at most four times a
// second; plain lines every few seconds where stderr is not a terminal and progress was
// asked for; nothing when quiet.
#pragma once

#include <string>

#include "render/renderer.h"

namespace pathcl::cli {

class ProgressLine {
public:
    enum class Mode { Auto, Lines, Quiet }; // Auto: the line on a terminal, else nothing

    ProgressLine(Mode mode, std::string label);
    ~ProgressLine(); // clears the line

    void show(const RenderProgress& p) { show(p, label_); }
    // With another label for this line (what is being rendered now).
    void show(const RenderProgress& p, const std::string& label);
    // Clears the self-updating line (before other output).
    void finish();

private:
    bool tty_ = false, lines_ = false, drawn_ = false;
    std::string label_;
    double last_ = -1.0;
};

// "1.2 s", "3 min 4 s", "2 h 05 min".
std::string format_duration(double seconds);

} // namespace pathcl::cli
