#include "gestura/studio/recovery.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gestura/core/error.hpp"

namespace gestura::studio {

std::string recovery_path(const std::string& user_db) { return user_db + ".studio-draft.json"; }

void write_recovery(const std::string& path, const SignDraft& draft) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(SourceLocation{temporary}, "cannot write the recovery file");
    out << nlohmann::json{{"gestura_studio_draft", 1}, {"draft", to_json(draft)}}.dump(1) << '\n';
    out.flush();
    if (!out) throw Error(SourceLocation{temporary}, "cannot write the recovery file (disk full?)");
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw Error(SourceLocation{path}, "cannot replace the recovery file");
  }
}

std::optional<SignDraft> read_recovery(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(SourceLocation{path}, "cannot read the recovery file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_recovery(text.str(), path);
}

SignDraft parse_recovery(std::string_view text, const std::string& name) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object() || !json.contains("draft"))
    throw Error(SourceLocation{name}, "the recovery file is not a studio draft (left in place)");
  try {
    return draft_from_json(json.at("draft"));
  } catch (const Error& e) {
    throw Error(SourceLocation{name}, e.message());
  }
}

void discard_recovery(const std::string& path) {
  std::error_code ec;
  std::filesystem::remove(path, ec);
}

}  // namespace gestura::studio
