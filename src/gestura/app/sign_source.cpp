#include "gestura/app/sign_source.hpp"

#include "gestura/app/error.hpp"
#include "gestura/sign/hamnosys_parser.hpp"

namespace gestura::app {

void validate(const SignSource& source) {
  check_fields(source);
  const int sources = !source.hamnosys.empty() + !source.names.empty() + !source.sigml.empty();
  if (sources != 1) usage_error(sources == 0 ? "hamnosys" : "", "give exactly one of --hamnosys, --names, --sigml");
  if (!source.gloss.empty() && source.sigml.empty()) usage_error("gloss", "chooses a sign of a --sigml file");
}

LoadedSign load_sign(const SignSource& source) {
  validate(source);
  // Notation given in the request is the request's field; its symbol index is the place.
  if (!source.hamnosys.empty())
    return {as_field_error(ErrorCategory::input, "hamnosys", [&] { return sign::parse_hamnosys_unicode(source.hamnosys); }), {}, {}};
  if (!source.names.empty())
    return {as_field_error(ErrorCategory::input, "names", [&] { return sign::parse_hamnosys_names(source.names); }), {}, {}};
  for (sign::SigmlSign& s : sign::read_sigml(sign::read_text_file(source.sigml), source.sigml))
    if (source.gloss.empty() || s.gloss == source.gloss) return {std::move(s.manual), std::move(s.nonmanual), source.sigml};
  if (source.gloss.empty()) throw AppError(ErrorCategory::input, Place{"sigml", {source.sigml}}, "no sign in this file");
  throw AppError(ErrorCategory::not_found, Place{"gloss", {source.sigml}}, "no sign with gloss '" + source.gloss + "'");
}

}  // namespace gestura::app
