/* Picking one light for a shadow ray in proportion to its power, through the alias table
 * of the light distribution (O(1); built by host/compile/light_distribution.cpp). The
 * probability that a light is picked is its distribution entry's pmf, which MIS needs
 * for BSDF-found hits on lights too. */
#include "kernel_data.cl"
#include "light/light_pick.h"

/* The light for the slot number *u and the alias coin u_alias. *u is then rescaled to
 * [0, 1) within its slot's steps, uniform again and independent of the pick, so that the
 * point on the light can take it: a 2D set of points spread over the slots leaves each
 * light a stratified share (Mitsuba 3 reuses a sample the same way to pick an emitter
 * and a mesh's triangle), rather than a random subset chosen by a dimension of its own
 * (docs/cameras-and-samplers.md, "Samplers"). The samplers' numbers are multiples of 2^-24, so *u alone
 * would leave a slot of s steps only s values (16 with a million lights): step_jitter,
 * an independent uniform number, places the result inside its step. */
static inline int light_pick(__global const LightAliasEntry* distribution, uint count, float* u, float u_alias,
                             float step_jitter)
{
    uint k = min((uint)(*u * (float)LIGHT_PICK_GRID), LIGHT_PICK_GRID - 1u);
    uint slot = light_pick_slot(k, count);
    ulong first = light_pick_first_step(slot, count), steps = light_pick_first_step(slot + 1u, count) - first;
    *u = min(((float)(k - (uint)first) + step_jitter) / (float)steps, 0x1.fffffep-1f);
    int i = (int)slot;
    uint coin = min((uint)(u_alias * (float)LIGHT_PICK_GRID), LIGHT_PICK_GRID - 1u);
    return (coin < distribution[i].alias_threshold) ? i : distribution[i].alias;
}
