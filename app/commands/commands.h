// The commands of `shadowlab`, one file each in app/commands/: each file holds its
// command's arguments, options and run, and one function that gives the subcommand main()
// made for it (app/main.cpp, the table of commands) its description, options and run.
#pragma once

#include <memory>

#include <CLI/CLI.hpp>

namespace shadowlab {

// The arguments a command's options fill in, owned by the command's callback, which runs
// `run` on them: they live as long as the subcommand, and no longer.
template <class Args, class Run>
Args& argumentsRunBy(CLI::App& command, Run run) {
    const auto args = std::make_shared<Args>();
    command.callback([args, run] { run(*args); });
    return *args;
}

void addRenderCommand(CLI::App& command);
void addSweepCommand(CLI::App& command);
void addMergeSweepCommand(CLI::App& command);
void addReportCommand(CLI::App& command);
void addScalingCommand(CLI::App& command);
void addFlythroughCommand(CLI::App& command);
void addCompareCommand(CLI::App& command);
void addBenchCommand(CLI::App& command);
void addTechniquesCommand(CLI::App& command);
void addExportObjCommand(CLI::App& command);
void addEnvironmentCommand(CLI::App& command);
void addCompositeCommand(CLI::App& command);

}  // namespace shadowlab
