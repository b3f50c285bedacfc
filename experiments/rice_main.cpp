// The `rice` command (experiments/command_line.hpp): studies, figures and grain sets.
#include "experiments/command_line.hpp"

int main(int argc, char** argv) { return rice::experiments::run_command_line(argc, argv); }
