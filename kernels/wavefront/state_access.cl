/* Reading and writing the wavefront's path state (wavefront/path_state.h): field f of
 * slot p is word f * capacity + p of the state buffer. */
#include "wavefront/path_state.h"

typedef struct {
    __global float* words;
    uint capacity;
} WavefrontState;

static inline float state_float(WavefrontState s, int field, uint p)
{
    return s.words[(uint)field * s.capacity + p];
}

static inline int state_int(WavefrontState s, int field, uint p)
{
    return ((__global const int*)s.words)[(uint)field * s.capacity + p];
}

static inline void state_set_float(WavefrontState s, int field, uint p, float v)
{
    s.words[(uint)field * s.capacity + p] = v;
}

static inline void state_set_int(WavefrontState s, int field, uint p, int v)
{
    ((__global int*)s.words)[(uint)field * s.capacity + p] = v;
}

#define STATE_F(s, name, p) state_float(s, WAVEFRONT_##name, p)
#define STATE_I(s, name, p) state_int(s, WAVEFRONT_##name, p)
#define STATE_SET_F(s, name, p, v) state_set_float(s, WAVEFRONT_##name, p, v)
#define STATE_SET_I(s, name, p, v) state_set_int(s, WAVEFRONT_##name, p, v)
