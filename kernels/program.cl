/* The render program: every kernel a render launches (camera rays, path tracing, film
 * clearing) and the sample visualizer's. Built by host/cl/cl_runtime.cpp with the scene's
 * feature mask (features.h); each file includes what it uses. */
#include "camera/camera.cl"
#include "film/film.cl"
#include "integrator/megakernel.cl"
#include "sample/sampler_points.cl"
