#include "sign_source.hpp"

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sigml.hpp"

namespace gestura::cli {

bool parse_sign_source_flag(const std::vector<std::string>& args, std::size_t& i, SignSource& source) {
  const std::string& a = args[i];
  if (a == "--hamnosys") source.hamnosys = flag_value(args, i);
  else if (a == "--names") source.names = flag_value(args, i);
  else if (a == "--sigml") source.sigml_path = flag_value(args, i);
  else if (a == "--gloss") source.gloss = flag_value(args, i);
  else return false;
  return true;
}

namespace {

sign::SigmlSign pick_sigml_sign(const SignSource& source) {
  const std::string& path = source.sigml_path;
  for (sign::SigmlSign& s : sign::read_sigml(sign::read_text_file(path), path))
    if (source.gloss.empty() || s.gloss == source.gloss) return std::move(s);
  throw Error(path + ": no sign" + (source.gloss.empty() ? std::string() : " with gloss '" + source.gloss + "'"));
}

}  // namespace

sign::HamSign load_sign(const SignSource& source) {
  const int sources = !source.hamnosys.empty() + !source.names.empty() + !source.sigml_path.empty();
  if (sources != 1) throw Error("give exactly one of --hamnosys, --names, --sigml");
  if (!source.hamnosys.empty()) return sign::parse_hamnosys_unicode(source.hamnosys);
  if (!source.names.empty()) return sign::parse_hamnosys_names(source.names);
  return pick_sigml_sign(source).manual;
}

std::vector<sign::NonManual> load_nonmanuals(const SignSource& source) {
  if (source.sigml_path.empty()) return {};
  return pick_sigml_sign(source).nonmanual;
}

}  // namespace gestura::cli
