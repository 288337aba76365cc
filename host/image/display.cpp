#include "image/display.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"

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

ToneCurve tone_curve_from_name(const std::string& name)
{
    if (name == "clip")
        return ToneCurve::Clip;
    if (name == "filmic")
        return ToneCurve::Filmic;
    throw Error("--tone: " + quote(name) + " is not clip or filmic");
}

} // namespace pathcl
