// pathcl: the command line of host/cli/command_line.h. Every error is one line on stderr
// ("pathcl: error: ...") and exit code 2; nothing is written unless the command
// succeeded.
#include "cli/command_line.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

int main(int argc, char** argv)
{
    int code = pathcl::cli::run_command_line(argc, argv);
#if defined(__SANITIZE_ADDRESS__)
    // In a sanitizer build, the leak check runs here, while the libraries' thread pools
    // (OpenEXR's, OpenImageIO's, PoCL's) sit idle. Left to exit, it runs after their
    // static destructors have stopped those threads, and LeakSanitizer's tracer can crash
    // on a thread that is still ending ("Tracer caught signal 11",
    // github.com/google/sanitizers/issues/1353). A leak is one at both points: the
    // command's own objects are destroyed by now, and what the libraries' statics hold
    // is still reachable from them.
    __lsan_do_leak_check();
#endif
    return code;
}
