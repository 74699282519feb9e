#pragma once
// The default avatar and its signing rig, built once per test run (building them takes a while)
// and shared by the sign-synthesis and fingerspelling tests.
#include "gestura/body/avatar.hpp"
#include "gestura/sign/signing_rig.hpp"

namespace gestura::test {

// Not copyable: the rig points at the avatar.
struct SigningAvatar {
  SigningAvatar() = default;
  SigningAvatar(const SigningAvatar&) = delete;
  SigningAvatar& operator=(const SigningAvatar&) = delete;
  Avatar avatar = build_avatar();
  SigningRig rig = make_signing_rig(avatar);
};

const SigningAvatar& signing_avatar();

}  // namespace gestura::test
