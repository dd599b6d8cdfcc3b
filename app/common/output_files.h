// What every command does with its output files: checks their destinations before the work,
// writes a measurement's STEM.csv, .json and .svg, and moves staged files into place.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include "app/common/staged_outputs.h"

namespace shadowlab {

// A command's output files are written one after another, each whole or not at all; so
// that a later one cannot fail after the earlier ones were written, every destination's
// directory is checked before any work is done (a path naming a directory fails too). An
// empty path is an output not asked for.
void requireOutputDirectories(std::initializer_list<const std::string*> paths);

// The three files of a sweep, scaling or fly-through: STEM.csv, STEM.json and STEM.svg.
void writeCsvJsonSvg(const std::filesystem::path& stem, const std::string& csv, const std::string& json,
                     const std::string& svg);

// The techniques of a sweep or fly-through as a part of its files' names: joined with '+'
// ("shadow-map+izb"), or, when that is longer than 96 characters (a file system refuses a name
// above 255 bytes, and the images folder and extension are added to it), the first name, how
// many more, and a hash of the whole list, so different lists keep different files
// ("none+30-more-1f3a9c07").
std::string techniqueListStem(const std::vector<std::string>& techniques);

// Moves a command's staged files into place and names those at the top of its folder (the
// pictures of --images, in subfolders, are not listed one by one).
void commitAndList(StagedOutputs& outputs);

}  // namespace shadowlab
