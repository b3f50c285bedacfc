// The `rice` command (experiments/cli/command_line.hpp): studies, figures and grain sets.
#include "experiments/cli/command_line.hpp"

int main(int argc, char** argv) { return rice::experiments::run_command_line(argc, argv); }
