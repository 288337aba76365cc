/* Where an emissive triangle is sampled by solid angle (--triangle-sampling solid-angle,
 * light/triangle.cl), written once for the kernels and the host's tests.
 *
 * A triangle is sampled by solid angle where it looks large from the shading point: its
 * area over the squared distance to its centroid (about its solid angle, and cheap to
 * test, so the solid angle itself is computed only where the test passes) exceeds
 * TRIANGLE_SOLID_ANGLE_MIN. Below it the area pdf varies little across the triangle and
 * solid-angle sampling costs more than it saves: 0.3 kept the Cornell box's efficiency
 * within 3 % of area sampling's and gained the most on a panel beside a wall
 * (docs/accuracy.md, "Triangle sampling"). Above TRIANGLE_SOLID_ANGLE_MAX steradians (a
 * point almost in the triangle's plane and inside it) Arvo's construction is
 * ill-conditioned, as pbrt-v4 notes; area sampling serves there too. */
#ifndef PATHCL_LIGHT_TRIANGLE_SAMPLING_H
#define PATHCL_LIGHT_TRIANGLE_SAMPLING_H

#define TRIANGLE_SOLID_ANGLE_MIN 0.3f
#define TRIANGLE_SOLID_ANGLE_MAX 6.22f

#endif
