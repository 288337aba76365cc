// pathcl: the command line of host/cli/command_line.h. Every error is one line on stderr
// ("pathcl: error: ...") and exit code 2; nothing is written unless the command
// succeeded.
#include "cli/command_line.h"
#include "common/early_leak_check.h"

int main(int argc, char** argv)
{
    int code = pathcl::cli::run_command_line(argc, argv);
    pathcl::check_leaks_now(); // in a sanitizer build, before the libraries' static destructors
    return code;
}
