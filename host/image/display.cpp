#include "image/display.h"

#include <algorithm>
#include <cmath>

namespace pathcl {

float display_value(float radiance, const DisplayTransform& display)
{
    double x = static_cast<double>(radiance);
    if (display.exposure_ev != 0.0)
        x *= std::exp2(display.exposure_ev);
    if (display.tone == ToneCurve::Filmic && x > 0.0)
        x = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
    return static_cast<float>(std::clamp(x, 0.0, 1.0));
}

} // namespace pathcl
