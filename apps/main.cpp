#include <csignal>
#include <string_view>

#include "apps/cli/Cli.h"
#include "apps/view/Viewer.h"

int main(int argc, char** argv)
{
    // Past a file size limit (ulimit -f) a write should fail with EFBIG, which the atomic
    // writer reports (core/AtomicFile.h), rather than kill the process with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    // The viewer has its own command line (and is the only part linking GLFW and ImGui).
    if (argc > 1 && std::string_view(argv[1]) == "view")
        return manylights::runViewCommand(argc - 1, argv + 1);
    return manylights::runCli(argc, argv);
}
