// pathcl: the command line of host/cli/command_line.h. Every error is one line on stderr
// ("pathcl: error: ...") and exit code 2; nothing is written unless the command
// succeeded.
#include "cli/command_line.h"

int main(int argc, char** argv)
{
    return pathcl::cli::run_command_line(argc, argv);
}
