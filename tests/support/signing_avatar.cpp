#include "support/signing_avatar.hpp"

namespace gestura::test {

const SigningAvatar& signing_avatar() {
  static const SigningAvatar built;
  return built;
}

}  // namespace gestura::test
