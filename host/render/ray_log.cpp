#include "render/ray_log.h"

#include <cstdio>
#include <fstream>

#include "common/error.h"
#include "common/staged_files.h"

namespace pathcl {

void check_ray_log_path(const std::string& path)
{
    if (lowercase_extension(path) != ".ply")
        throw ParameterError("ray_log", path + " must be a .ply file");
    check_output_location(path);
}

void write_ray_log_file(const std::string& file, const std::string& path, const std::vector<CameraRayRecord>& rays)
{
    check_ray_log_path(path);
    std::ofstream out(file, std::ios::binary);
    out << "ply\nformat ascii 1.0\ncomment pathcl camera rays: origin (world space), unit direction as normal\n"
        << "element vertex " << rays.size() << "\n"
        << "property double x\nproperty double y\nproperty double z\n"
        << "property float nx\nproperty float ny\nproperty float nz\n"
        << "property uint pixel_x\nproperty uint pixel_y\nproperty uint sample\nend_header\n";
    char line[256];
    for (const CameraRayRecord& r : rays) {
        std::snprintf(line, sizeof line, "%.17g %.17g %.17g %.9g %.9g %.9g %u %u %u\n", r.origin.x, r.origin.y,
                      r.origin.z, static_cast<double>(r.direction.x), static_cast<double>(r.direction.y),
                      static_cast<double>(r.direction.z), r.x, r.y, r.sample);
        out << line;
    }
    out.flush();
    if (!out)
        throw Error(path + ": cannot write");
}

void write_ray_log(const std::string& path, const std::vector<CameraRayRecord>& rays)
{
    StagedFiles staged;
    write_ray_log_file(staged.stage(path), path, rays);
    staged.commit();
}

} // namespace pathcl
