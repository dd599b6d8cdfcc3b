// The lessons (docs/lessons/): each page's title names the lesson by its file's number,
// written alike ("Lesson 8", not "Lesson 08").
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace std::string_literals;

TEST_CASE("lessons: each title is Lesson N, N its file's number without leading zeros") {
    const std::filesystem::path root = SHADOWLAB_SOURCE_DIR;
    int lessons = 0;
    for (const auto& entry : std::filesystem::directory_iterator(root / "docs/lessons")) {
        const std::string file = entry.path().filename().string();
        if (file.size() < 3 || !std::isdigit(static_cast<unsigned char>(file[0])) || file[2] != '-') continue;
        std::ifstream in(entry.path());
        std::string first;
        std::getline(in, first);
        INFO(file << ": " << first);
        CHECK(first.starts_with("# Lesson "s + std::to_string(std::stoi(file.substr(0, 2))) + ":"));
        ++lessons;
    }
    CHECK(lessons >= 14);
}
