/* The render program: every kernel a render launches (camera rays, path tracing, film
 * clearing; the wavefront integrator's stages when built with -DPATHCL_WAVEFRONT) and the
 * sample visualizer's. Built by host/cl/cl_runtime.cpp with the scene's feature mask
 * (features.h); each file includes what it uses. */
#include "camera/camera.cl"
#include "film/film.cl"
#include "integrator/megakernel.cl"
#include "sample/sampler_points.cl"
#ifdef PATHCL_WAVEFRONT
#include "wavefront/wavefront.cl"
#endif
