#include "support/device_fixture.h"

#include <fstream>
#include <sstream>

#include "common/error.h"

namespace pathcl::test {

ClDevice& test_device()
{
    static ClDevice dev = open_device(0);
    return dev;
}

std::string read_text_file(const std::string& path)
{
    std::ifstream f(path);
    if (!f)
        throw Error(path + ": cannot open");
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

cl::Program build_test_program(const std::string& file, const std::string& defines)
{
    std::string src = read_text_file(std::string(PATHCL_SOURCE_DIR) + "/tests/kernels/" + file);
    return build_program(test_device(), defines, {src}).program;
}

} // namespace pathcl::test
