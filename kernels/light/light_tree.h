/* The light tree's importance of a node at a shading point (Conty Estevez and Kulla 2018,
 * "Importance Sampling of Many Lights with Adaptive Tree Splitting", section 4.2), written
 * once for the kernels' descent (light/light_tree.cl, float) and the host's tests (double).
 * The caller computes the geometry; this is the bound on how much of the node's power
 * can reach the point:
 *   phi cos(theta') / d^2, times cos(theta'_i) at a surface,
 * where theta' is the smallest angle between the direction from the node to the point and
 * any direction the node's lights emit along (the normals' cone widened by the box's
 * angular size), and theta'_i the smallest angle between the shading normal and any
 * direction to the box. Zero where no light of the node can emit towards the point. */
#ifndef PATHCL_LIGHT_LIGHT_TREE_H
#define PATHCL_LIGHT_LIGHT_TREE_H

#include "util/compat.h"

PATHCL_BEGIN

/* cos(max(0, a - b)) from the cosines and sines of angles a, b in [0, pi]. */
PATHCL_FN pcl_real cos_of_clamped_difference(pcl_real cos_a, pcl_real sin_a, pcl_real cos_b, pcl_real sin_b)
{
    return cos_a > cos_b ? PCL_REAL(1.0) : cos_a * cos_b + sin_a * sin_b;
}

/* sin(max(0, a - b)), likewise. */
PATHCL_FN pcl_real sin_of_clamped_difference(pcl_real cos_a, pcl_real sin_a, pcl_real cos_b, pcl_real sin_b)
{
    return cos_a > cos_b ? PCL_REAL(0.0) : sin_a * cos_b - cos_a * sin_b;
}

PATHCL_FN pcl_real sin_from_cos(pcl_real c)
{
    return sqrt(fmax(PCL_REAL(0.0), PCL_REAL(1.0) - c * c));
}

/* The importance of a node of power phi whose lights' normals lie within theta_o of its
 * axis and emit up to theta_e beyond it, seen from a point at squared distance d2 from the
 * box's centre (clamped by the caller to the box's half diagonal squared) along a direction
 * at cos_w to the axis (made absolute for two-sided lights), where the box subtends a cone
 * of half-angle theta_b (cos_b -1 from inside its bounding sphere). cos_i: the absolute
 * cosine between the direction to the box's centre and the shading normal (light through
 * either side counts: transmission), or a value above 1 where no normal is to count. */
PATHCL_FN pcl_real light_cone_importance(pcl_real phi, pcl_real cos_o, pcl_real cos_e, pcl_real d2, pcl_real cos_w,
                                         pcl_real cos_b, pcl_real cos_i)
{
    pcl_real sin_w = sin_from_cos(cos_w), sin_o = sin_from_cos(cos_o), sin_b = sin_from_cos(cos_b);
    /* theta_x = max(0, theta_w - theta_o), then theta' = max(0, theta_x - theta_b). */
    pcl_real cos_x = cos_of_clamped_difference(cos_w, sin_w, cos_o, sin_o);
    pcl_real sin_x = sin_of_clamped_difference(cos_w, sin_w, cos_o, sin_o);
    pcl_real cos_p = cos_of_clamped_difference(cos_x, sin_x, cos_b, sin_b);
    if (cos_p < cos_e)
        return PCL_REAL(0.0);
    pcl_real importance = phi * cos_p / d2;
    if (cos_i <= PCL_REAL(1.0))
        importance *= cos_of_clamped_difference(cos_i, sin_from_cos(cos_i), cos_b, sin_b);
    return fmax(importance, PCL_REAL(0.0));
}

PATHCL_END

#endif
