#include "apps/cli/DevicesCommand.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "core/Error.h"
#include "platform/EglChoice.h"
#include "platform/HeadlessContext.h"

namespace manylights {

void printDevices()
{
    const std::vector<EglDeviceInfo> devices = listDevices();
    if (devices.empty()) {
        const EglPlatformChoice choice = eglPlatformChoice();
        throw Error("no EGL devices to list (" +
                    (choice.canEnumerateDevices ? std::string("EGL lists none")
                                                : "EGL cannot enumerate them: " + choice.reason) +
                    "); render and bench still try Mesa's surfaceless platform");
    }
    // Columns as wide as their longest entry, so that the table reads in a terminal and splits
    // on runs of spaces in a script. The UUID comes last, so that the columns scripts read
    // before it (issue 30) keep their places.
    std::vector<std::string> renderers;
    std::size_t vendorWidth = std::string("vendor").size();
    std::size_t rendererWidth = std::string("renderer").size();
    std::size_t fileWidth = std::string("device file").size();
    for (const EglDeviceInfo& device : devices) {
        renderers.push_back(device.problem.empty() ? device.renderer : "(" + device.problem + ")");
        vendorWidth = std::max(vendorWidth, device.vendor.size());
        rendererWidth = std::max(rendererWidth, renderers.back().size());
        fileWidth = std::max(fileWidth, device.drmFile.size());
    }
    std::printf("%-5s  %-*s  %-*s  %-8s  %-*s  %s\n", "index", int(vendorWidth), "vendor", int(rendererWidth),
                "renderer", "software", int(fileWidth), "device file", "uuid");
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const EglDeviceInfo& device = devices[i];
        std::printf("%-5d  %-*s  %-*s  %-8s  %-*s  %s\n", device.index, int(vendorWidth),
                    device.vendor.empty() ? "-" : device.vendor.c_str(), int(rendererWidth), renderers[i].c_str(),
                    device.software ? "yes" : "no", int(fileWidth),
                    device.drmFile.empty() ? "-" : device.drmFile.c_str(),
                    device.uuid ? formatUuid(*device.uuid).c_str() : "-");
    }
    std::fflush(stdout);
}

}  // namespace manylights
