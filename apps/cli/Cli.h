// The manylights command line (docs/cli.md). main() only forwards here, so tests can drive
// the exact code path users run.
#pragma once

namespace manylights {

// Exit status: 0 success, 2 bad command line, 1 anything else (one line on stderr).
int runCli(int argc, const char* const* argv);

}  // namespace manylights
