#pragma once
/// @file commands.hpp
/// @brief The subcommands of the `lucent` CLI; each returns the process exit code.
namespace lucent::cli {

int runRender(int argc, char** argv);
int runProfile(int argc, char** argv);
int runMaterials(int argc, char** argv);
int runCompare(int argc, char** argv);
int runBench(int argc, char** argv);
int runTechniques(int argc, char** argv);
int runReport(int argc, char** argv);
int runPlan(int argc, char** argv);

/// The whole CLI: dispatches to a subcommand, turns bad input into one line and exit code 2.
int run(int argc, char** argv);

}  // namespace lucent::cli
