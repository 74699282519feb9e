#pragma once
// The one place that decides what `gestura render` and `gestura view` show: the default avatar
// (build_avatar, with --height/--build/--sex as in `gestura avatar export`) at rest, doing the
// built-in test wave, playing a motion file whose joints are the avatar's own (H-Anim names), or
// performing a sign (sign_source.hpp).
#include <string>
#include <vector>

#include "gestura/body/avatar_params.hpp"
#include "gestura/render/subject.hpp"
#include "sign_source.hpp"

namespace gestura::cli {

enum class Motion { Rest, TestMotion, ClipFile, Sign };

// Avatar flags shared by render and view. When args[i] is --height, --build, --sex or --avatar
// SPEC (see load_avatar), reads its value into `params` / `spec` (advancing i) and returns true; a
// bad value throws gestura::Error naming the flag. Call params.validate() after the loop.
bool parse_avatar_flag(const std::vector<std::string>& args, std::size_t& i, AvatarParams& params, std::string& spec);

// Builds the avatar once and attaches the motion. Throws gestura::Error for invalid params, a
// clip file that cannot be read (file:line:col from the reader) or one whose joints are not the
// avatar's (a few of the unmatched names are listed). Motion::Sign performs `sign_source` (parsed before the
// avatar is built, so bad notation fails at once) and warns on stderr when synthesis_problem finds one.
// `avatar_spec` chooses the body (see load_avatar).
RenderSubject load_render_subject(Motion motion, const std::string& clip_path, const AvatarParams& params,
                                  const SignSource& sign_source = {}, const std::string& avatar_spec = "default");

}  // namespace gestura::cli
