// The camera-ray log (`pathcl render --ray-log FILE.ply`): a subsample of the camera rays
// as a PLY point cloud, one vertex per ray at its world-space origin with the ray's unit
// direction as the vertex normal (x, y, z, nx, ny, nz), plus the pixel and sample index.
// Point-cloud viewers (MeshLab, CloudCompare, Blender) show the directions as normals.
#pragma once

#include <string>
#include <vector>

#include "render/renderer.h"

namespace pathcl {

// Throws pathcl::Error unless `path` ends in .ply and its directory exists.
void check_ray_log_path(const std::string& path);

// ASCII PLY, written under a temporary name and renamed (never a partial file).
void write_ray_log(const std::string& path, const std::vector<CameraRayRecord>& rays);

// The log for `path` written to `file` (a temporary name from StagedFiles).
void write_ray_log_file(const std::string& file, const std::string& path, const std::vector<CameraRayRecord>& rays);

} // namespace pathcl
