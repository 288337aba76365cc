// `pathcl devices`: every OpenCL platform and device, with the index --device takes, its
// driver's version and the workarounds pathcl applies on it (cl/device_workarounds.h).
#include <cstdio>
#include <iostream>

#include "cl/cl_runtime.h"
#include "cl/device_workarounds.h"
#include "cli/commands.h"
#include "cli/help_format.h"

namespace pathcl::cli {

Command add_devices_command(CLI::App& app)
{
    CLI::App* devices = app.add_subcommand("devices", "List every OpenCL platform and device with its index");
    describe_command(
        devices, {},
        {{"pathcl devices", "every device with the index --device takes"},
         {"pathcl render scenes/cornell-box.gltf -o box.png --device 0,1", "then two of them sharing one render"}});
    return {devices, [] {
                std::vector<DeviceInfo> list = list_devices();
                if (list.empty()) {
                    std::cout << "no OpenCL devices found\n";
                    return 1;
                }
                for (const DeviceInfo& d : list)
                    std::printf("%d: %s | %s | %s | %u compute units | %.1f GiB | %s | driver %s%s%s%s\n", d.index,
                                d.platform.c_str(), d.name.c_str(), d.type.c_str(), d.compute_units,
                                static_cast<double>(d.global_memory) / (1024.0 * 1024.0 * 1024.0), d.version.c_str(),
                                d.driver.c_str(), d.fp64 ? " | fp64" : "",
                                d.correctly_rounded_divide_sqrt ? " | IEEE div/sqrt" : "",
                                needs_kernel_width_hint(d) ? " | workaround: kernel width hint" : "");
                return 0;
            }};
}

} // namespace pathcl::cli
