#pragma once
// Names nobody can guess or collide with by chance: job ids, temporary file names, room
// reconnect tokens. Safe to call from any thread.
#include <string>

namespace gestura::serve {

// `words` × 64 random bits as lowercase hex (16 characters per word).
std::string random_hex(int words = 1);

}  // namespace gestura::serve
