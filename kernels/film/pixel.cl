/* Which pixel a work-item of a 2D image kernel renders: work-item (x, y) is pixel
 * (x, first_row + y), index row * width + x. first_row is the first row of the device's
 * band (several devices share an image by rows): a parameter rather than a global work
 * offset, for which PoCL compiles a second work-group function. The global size is rounded
 * up to whole work-groups, so the work-items past the image's edge have none; a band's end
 * needs no check, as bands end on multiples of every tile height. Adaptive sampling
 * (frame->adaptive) also skips the pixels the host has marked converged in the film
 * array `active`. */
#include "types.h"

static inline bool frame_pixel(const FrameParams* frame, uint2* xy, uint* pixel)
{
    uint x = get_global_id(0);
    uint y = frame->first_row + (uint)get_global_id(1);
    *xy = (uint2)(x, y);
    *pixel = y * frame->width + x;
    return x < frame->width && y < frame->height;
}

static inline bool pixel_active(const FrameParams* frame, __global const uint* active, uint pixel)
{
    return frame->adaptive == 0u || active[pixel] != 0u;
}
