#pragma once
// The default avatar as a render subject with the built-in wave clip, built once per test run
// (building it takes a while) and shared by the render tests.
#include "gestura/render/subject.hpp"

namespace gestura {

const RenderSubject& default_avatar_subject();

}  // namespace gestura
