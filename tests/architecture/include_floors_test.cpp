// Dependencies point down only. docs/architecture.md lists the library's folders as floors, top
// floor first, in a ```floors block; this test reads that block and every source file, and fails
// for an include that climbs: a folder including one on a higher floor, or on its own floor beside
// it. Within one folder the units (a .hpp and its .cpp) must not include each other round in a
// circle: one of them would be a floor above the other.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/build_paths.hpp"

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Folder → floor (0 = bottom), from the ```floors block: one floor a line, top first, the folders
// of one floor separated by spaces or "·".
std::map<std::string, int> floors_from_doc() {
  const std::string doc = read(fs::path(gestura::test::source_dir()) / "docs" / "architecture.md");
  const auto begin = doc.find("```floors\n");
  if (begin == std::string::npos) return {};
  const auto end = doc.find("```", begin + 10);
  std::istringstream block(doc.substr(begin + 10, end - begin - 10));
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(block, line);) {
    line = line.substr(0, line.find("--"));  // what follows "--" explains the floor
    std::istringstream words(std::regex_replace(line, std::regex("·"), " "));
    std::vector<std::string> names;
    for (std::string w; words >> w;) names.push_back(w);
    if (!names.empty()) lines.push_back(names);
  }
  std::map<std::string, int> floor;
  for (std::size_t i = 0; i < lines.size(); ++i)
    for (const std::string& name : lines[i]) floor[name] = static_cast<int>(lines.size() - 1 - i);
  return floor;
}

struct Include {
  std::string file;    // relative to the checkout
  std::string folder;  // the including file's folder under src/gestura
  std::string target;  // "sign/hand_solver.hpp"
};

std::vector<Include> library_includes() {
  const fs::path root = fs::path(gestura::test::source_dir());
  const std::regex include_line(R"re(^\s*#\s*include\s*"gestura/([a-z_0-9]+/[A-Za-z_0-9./]+)")re");
  std::vector<Include> out;
  for (const auto& entry : fs::recursive_directory_iterator(root / "src" / "gestura")) {
    const fs::path& p = entry.path();
    if (!entry.is_regular_file() || (p.extension() != ".hpp" && p.extension() != ".cpp")) continue;
    const std::string rel = fs::relative(p, root / "src" / "gestura").generic_string();
    const std::string folder = rel.substr(0, rel.find('/'));
    std::istringstream text(read(p));
    for (std::string line; std::getline(text, line);) {
      std::smatch m;
      if (std::regex_search(line, m, include_line)) out.push_back({"src/gestura/" + rel, folder, m[1].str()});
    }
  }
  return out;
}

std::string folder_of(const std::string& target) { return target.substr(0, target.find('/')); }

TEST(IncludeFloors, TheArchitectureDocListsEveryFolder) {
  const auto floor = floors_from_doc();
  ASSERT_FALSE(floor.empty()) << "docs/architecture.md has no ```floors block";
  for (const auto& entry : fs::directory_iterator(fs::path(gestura::test::source_dir()) / "src" / "gestura")) {
    if (!entry.is_directory()) continue;
    EXPECT_TRUE(floor.count(entry.path().filename().string()))
        << "src/gestura/" << entry.path().filename().string() << " has no floor in docs/architecture.md";
  }
}

TEST(IncludeFloors, NoFolderIncludesAFloorAboveOrBesideIt) {
  const auto floor = floors_from_doc();
  ASSERT_FALSE(floor.empty());
  const auto includes = library_includes();
  EXPECT_GT(includes.size(), 500u);  // the scan found the sources
  for (const Include& inc : includes) {
    const std::string to = folder_of(inc.target);
    if (to == inc.folder || !floor.count(inc.folder) || !floor.count(to)) continue;  // unknown folders: the test above
    EXPECT_LT(floor.at(to), floor.at(inc.folder))
        << inc.file << " includes gestura/" << inc.target << ": " << inc.folder << " (floor " << floor.at(inc.folder)
        << ") may include only folders below it, and " << to << " is on floor " << floor.at(to);
  }
}

TEST(IncludeFloors, UnitsOfAFolderDoNotIncludeEachOtherInACircle) {
  // A unit is a header and its source: "sign/hand_solver" stands for both. A header without a
  // source of its own (body/skinning_kernels.hpp: the kernels behind skinning.cpp and
  // skinning_avx2.cpp) is a private part of the units that include it, not a unit: its includes
  // count as theirs.
  const auto includes = library_includes();
  auto unit = [](const std::string& path) { return path.substr(0, path.rfind('.')); };
  std::set<std::string> with_source;
  std::map<std::string, std::set<std::string>> direct;
  for (const Include& inc : includes) {
    const std::string file = inc.file.substr(std::string("src/gestura/").size());
    if (file.ends_with(".cpp")) with_source.insert(unit(file));
    const std::string to = unit(inc.target);
    if (folder_of(to) == inc.folder) direct[unit(file)].insert(to);
  }
  std::map<std::string, std::set<std::string>> uses;
  for (const auto& [from, tos] : direct) {
    if (!with_source.count(from)) continue;
    std::vector<std::string> todo(tos.begin(), tos.end());
    std::set<std::string> seen;
    while (!todo.empty()) {
      const std::string to = todo.back();
      todo.pop_back();
      if (!seen.insert(to).second) continue;
      if (with_source.count(to)) {
        if (to != from) uses[from].insert(to);
      } else {
        for (const std::string& next : direct[to]) todo.push_back(next);
      }
    }
  }
  // Depth-first search for a back edge; the circle found is printed.
  std::map<std::string, int> state;  // 0 new, 1 on the path, 2 done
  std::vector<std::string> path;
  std::vector<std::string> circles;
  std::function<void(const std::string&)> visit = [&](const std::string& u) {
    state[u] = 1;
    path.push_back(u);
    for (const std::string& v : uses[u]) {
      if (state[v] == 1) {
        std::string circle;
        for (auto it = std::find(path.begin(), path.end(), v); it != path.end(); ++it) circle += *it + " → ";
        circles.push_back(circle + v);
      } else if (state[v] == 0) {
        visit(v);
      }
    }
    path.pop_back();
    state[u] = 2;
  };
  std::vector<std::string> units;
  for (const auto& [u, _] : uses) units.push_back(u);
  for (const std::string& u : units)
    if (state[u] == 0) visit(u);
  for (const std::string& c : circles) ADD_FAILURE() << "units include each other in a circle: " << c;
}

}  // namespace
