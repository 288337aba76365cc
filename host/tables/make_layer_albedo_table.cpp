// Build-time generator of the dielectric layer's albedo table (host/tables/layer_albedo.h):
// writes a C++ source defining pathcl::layer_albedo_table(). Run by CMake; takes about ten
// seconds on two cores (most of it the anisotropic table), which every render would
// otherwise pay on its first glossy material.
//   make_layer_albedo_table OUT.cpp
#include <cstdio>
#include <fstream>
#include <string>

#include "tables/layer_albedo.h"

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_layer_albedo_table OUT.cpp\n");
        return 2;
    }
    std::vector<float> table = pathcl::compute_layer_albedo_table();
    std::string tmp = std::string(argv[1]) + ".tmp";
    {
        std::ofstream out(tmp);
        out << "// Generated at build time by host/tables/make_layer_albedo_table.cpp; do not edit.\n"
               "#include \"tables/layer_albedo.h\"\n\nnamespace pathcl {\nnamespace {\nconst float kTable[] = {\n";
        char buf[32];
        for (std::size_t i = 0; i < table.size(); ++i) {
            std::snprintf(buf, sizeof buf, "%.9ef,%s", static_cast<double>(table[i]), i % 8 == 7 ? "\n" : " ");
            out << buf;
        }
        out << "};\n} // namespace\n\nconst std::vector<float>& layer_albedo_table()\n{\n"
               "    static const std::vector<float> table(std::begin(kTable), std::end(kTable));\n"
               "    return table;\n}\n\n} // namespace pathcl\n";
        if (!out) {
            std::fprintf(stderr, "make_layer_albedo_table: cannot write %s\n", tmp.c_str());
            return 1;
        }
    }
    return std::rename(tmp.c_str(), argv[1]) == 0 ? 0 : 1;
}
