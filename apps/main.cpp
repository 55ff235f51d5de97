#include <string_view>

#include "apps/cli/Cli.h"
#include "apps/view/Viewer.h"

int main(int argc, char** argv)
{
    // The viewer has its own command line (and is the only part linking GLFW and ImGui).
    if (argc > 1 && std::string_view(argv[1]) == "view")
        return manylights::runViewCommand(argc - 1, argv + 1);
    return manylights::runCli(argc, argv);
}
