#pragma once
// Autosave of the draft: the studio writes the draft it is editing to a recovery file beside the
// user lexicon whenever the draft has unsaved changes, and removes it when the draft is saved or the
// studio closes normally. A recovery file found at start-up means the last session did not end
// normally (crash, kill, power cut): the studio offers the draft back.
#include <optional>
#include <string>
#include <string_view>

#include "gestura/studio/sign_draft.hpp"

namespace gestura::studio {

// "<user_db>.studio-draft.json"
std::string recovery_path(const std::string& user_db);

// Writes atomically (a temporary file renamed over the old one), so a kill during the write leaves
// the previous draft. Throws gestura::Error naming the file when it cannot be written.
void write_recovery(const std::string& path, const SignDraft& draft);

// nullopt when there is no recovery file. Throws gestura::Error (naming the file) for one that cannot
// be read or is not a draft; the file is left alone so nothing is lost.
std::optional<SignDraft> read_recovery(const std::string& path);

// The recovery file's text as a draft; `name` is used in messages. Throws gestura::Error for text
// that is not a studio draft.
SignDraft parse_recovery(std::string_view text, const std::string& name);

// Removes the recovery file (no error when there is none).
void discard_recovery(const std::string& path);

}  // namespace gestura::studio
