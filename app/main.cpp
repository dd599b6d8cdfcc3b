// shadowlab: renders, compares and benchmarks shadow techniques (docs/commands.md).
// Every command exits non-zero with a one-line error on bad input, and writes its output
// files whole or not at all. Each command is a file of app/commands/; this is their table.
#include <iostream>
#include <stdexcept>
#include <string>

#include <malloc.h>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/commands/options.h"
#include "scenes/error_text.h"

using namespace shadowlab;

namespace {

struct Command {
    const char* name;
    void (*add)(CLI::App& command);   // its description, options and run
};

// In the order `shadowlab --help` lists them.
constexpr Command kCommands[] = {
    {"render", addRenderCommand},
    {"sweep", addSweepCommand},
    {"merge-sweep", addMergeSweepCommand},
    {"report", addReportCommand},
    {"scaling", addScalingCommand},
    {"flythrough", addFlythroughCommand},
    {"compare", addCompareCommand},
    {"bench", addBenchCommand},
    {"techniques", addTechniquesCommand},
    {"export-obj", addExportObjCommand},
    {"environment", addEnvironmentCommand},
    {"composite", addCompositeCommand},
};

// CLI11 answers a mistyped command with "A subcommand is required"; name it instead.
void requireKnownCommand(int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') return;
    std::string known;
    for (const Command& command : kCommands) {
        if (argv[1] == std::string(command.name)) return;
        known += (known.empty() ? "" : ", ") + std::string(command.name);
    }
    throw std::invalid_argument("unknown command '" + std::string(argv[1]) + "' (known: " + known + ")");
}

// Frames allocate their buffers afresh (maps, G-buffers, lists: tens of MB each), and a
// fresh page costs a fault and a zero fill, about 5 us per 4 KiB on the VMs we measure on:
// some 20 ms for one 2048^2 map. A renderer keeps such buffers from frame to frame; this
// program gets the same effect by keeping freed memory for reuse: every block comes from
// the heap (no mmap, whose threshold cannot exceed 32 MiB, so the 32 MiB moment maps of
// evsm and msm would be mapped and faulted afresh every frame) and the heap is never
// trimmed, so only the first (warm-up) frame pays the faults. Set once, before any work,
// by the program, not by the library (docs/peers.md, "Measured").
void keepFreedMemoryForReuse() {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, -1);
    mallopt(M_MMAP_MAX, 0);
}

}  // namespace

int main(int argc, char** argv) {
    keepFreedMemoryForReuse();
    CLI::App app{"shadowlab: a deterministic CPU rasterizer for studying real-time shadows"};
    app.require_subcommand(1);
    // One line whatever the message quotes (scenes/error_text.h).
    app.failure_message([](const CLI::App*, const CLI::Error& e) { return "shadowlab: error: " + oneLine(e.what()) + "\n"; });
    // Each command's callback runs its work during parse().
    for (const Command& command : kCommands) command.add(*app.add_subcommand(command.name));
    requireFiniteFloats(app);
    try {
        requireKnownCommand(argc, argv);
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error);
    } catch (const std::exception& error) {
        std::cerr << "shadowlab: error: " << oneLine(error.what()) << "\n";
        return 1;
    }
    return 0;
}
