/* Picking one light for a shadow ray in proportion to its power, through the alias table
 * of the light distribution (O(1); built by host/render/light_distribution.cpp). The
 * probability that a light is picked is its distribution entry's pmf, which MIS needs
 * for BSDF-found hits on lights too. */
#include "kernel_data.cl"
#include "light/light_pick.h"

/* The light for the slot number u_index and the alias coin u_alias. */
static inline int light_pick(__global const LightAliasEntry* distribution, uint count, float u_index, float u_alias)
{
    uint k = min((uint)(u_index * (float)LIGHT_PICK_GRID), LIGHT_PICK_GRID - 1u);
    int i = (int)light_pick_slot(k, count);
    uint coin = min((uint)(u_alias * (float)LIGHT_PICK_GRID), LIGHT_PICK_GRID - 1u);
    return (coin < distribution[i].alias_threshold) ? i : distribution[i].alias;
}
