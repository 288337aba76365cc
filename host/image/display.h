// What an 8-bit output (PNG) shows of linear radiance: an exposure in stops, then a tone
// curve, then the sRGB encoding (image_io). EXR outputs are linear and never pass through
// this. Clip is the identity clamped to [0, 1] (the default: bit for bit what PNGs were
// before the option existed); Filmic is Narkowicz's fit of the ACES reference rendering
// transform, x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), which rolls bright values off
// towards white instead of clipping them (f(1) = 0.80, f(4) = 0.97).
#pragma once

namespace pathcl {

enum class ToneCurve { Clip, Filmic };

struct DisplayTransform {
    double exposure_ev = 0.0; // radiance x 2^exposure_ev
    ToneCurve tone = ToneCurve::Clip;
};

// Linear radiance to display-linear [0, 1] (before the sRGB encoding).
float display_value(float radiance, const DisplayTransform& display);

} // namespace pathcl
