#include "apps/cli/Cli.h"

int main(int argc, char** argv) { return manylights::runCli(argc, argv); }
