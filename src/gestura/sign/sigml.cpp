#include "gestura/sign/sigml.hpp"

#include <algorithm>
#include <fstream>
#include <pugixml.hpp>

#include "gestura/core/error.hpp"
#include "gestura/sign/sign_limits.hpp"

namespace gestura::sign {
namespace {

// Maps byte offsets of the document to 1-based lines and columns.
class LineIndex {
 public:
  explicit LineIndex(std::string_view text) {
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') line_starts_.push_back(i + 1);
  }
  int line(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), static_cast<std::size_t>(offset));
    return static_cast<int>(it - line_starts_.begin());
  }
  int column(std::ptrdiff_t offset) const {
    const int l = line(offset);
    return l <= 0 ? 0 : static_cast<int>(static_cast<std::size_t>(offset) - line_starts_[static_cast<std::size_t>(l - 1)]) + 1;
  }

 private:
  std::vector<std::size_t> line_starts_{0};
};

[[noreturn]] void fail_at(std::string_view file, int line, int column, const std::string& message) {
  SourceLocation where;
  where.file = std::string(file);
  where.line = line;
  where.column = column;
  throw Error(where, message);
}

struct Context {
  std::string_view file;
  const LineIndex& lines;
  ParseOptions options;
  int line_of(const pugi::xml_node& n) const { return lines.line(n.offset_debug()); }
};

std::optional<NonManualTier> tier_from_element(std::string_view name) {
  if (name == "hnm_shoulder") return NonManualTier::shoulder;
  if (name == "hnm_body") return NonManualTier::body;
  if (name == "hnm_head") return NonManualTier::head;
  if (name == "hnm_eyegaze") return NonManualTier::eye_gaze;
  if (name == "hnm_eyebrows") return NonManualTier::eyebrows;
  if (name == "hnm_eyelids") return NonManualTier::eyelids;
  if (name == "hnm_nose") return NonManualTier::nose;
  if (name == "hnm_cheeks") return NonManualTier::cheeks;
  if (name == "hnm_mouthgesture") return NonManualTier::mouth_gesture;
  if (name == "hnm_mouthpicture") return NonManualTier::mouth_picture;
  if (name == "hnm_extra") return NonManualTier::extra;
  return std::nullopt;
}

void read_nonmanual(const Context& ctx, const pugi::xml_node& tiers, SigmlSign& sign) {
  for (const pugi::xml_node& n : tiers.children()) {
    if (n.type() != pugi::node_element) continue;
    const auto tier = tier_from_element(n.name());
    const int line = ctx.line_of(n);
    if (!tier) fail_at(ctx.file, line, 0, std::string("unknown non-manual element <") + n.name() + ">: expected hnm_head, hnm_eyebrows, hnm_mouthpicture, ...");
    const char* attribute = *tier == NonManualTier::mouth_picture ? "picture" : "tag";
    const pugi::xml_attribute value = n.attribute(attribute);
    if (!value) fail_at(ctx.file, line, 0, std::string("<") + n.name() + "> needs a " + attribute + " attribute");
    sign.nonmanual.push_back({*tier, value.value(), line});
  }
}

// Re-throws a notation error with the line of the element holding the offending symbol.
[[noreturn]] void rethrow_with_line(const Context& ctx, const SigmlSign& sign, const Error& e) {
  const int index = e.where().index;
  const int line = index >= 0 && index < static_cast<int>(sign.symbol_lines.size())
                       ? sign.symbol_lines[static_cast<std::size_t>(index)]
                       : sign.line;
  SourceLocation where;
  where.file = std::string(ctx.file);
  where.line = line;
  where.index = index;
  throw Error(where, "sign '" + sign.gloss + "': " + e.message());
}

SigmlSign read_hns_sign(const Context& ctx, const pugi::xml_node& node) {
  SigmlSign sign;
  sign.gloss = node.attribute("gloss").value();
  sign.line = ctx.line_of(node);
  bool have_manual = false;
  for (const pugi::xml_node& part : node.children()) {
    if (part.type() != pugi::node_element) continue;
    const std::string_view name = part.name();
    if (name == "hamnosys_nonmanual") {
      read_nonmanual(ctx, part, sign);
    } else if (name == "hamnosys_manual") {
      have_manual = true;
      for (const pugi::xml_node& s : part.children()) {
        if (s.type() != pugi::node_element) continue;
        const auto symbol = symbol_from_name(s.name());
        if (!symbol)
          fail_at(ctx.file, ctx.line_of(s), 0,
                  "sign '" + sign.gloss + "': unknown HamNoSys element <" + s.name() + ">: expected a symbol such as <hamflathand/>");
        if (sign.symbols.size() >= kMaxSignSymbols)
          fail_at(ctx.file, ctx.line_of(s), 0, "sign '" + sign.gloss + "': more than " + std::to_string(kMaxSignSymbols) + " symbols");
        sign.symbols.push_back(*symbol);
        sign.symbol_lines.push_back(ctx.line_of(s));
      }
    } else {
      fail_at(ctx.file, ctx.line_of(part), 0,
              "unexpected <" + std::string(name) + "> in <hns_sign>: expected <hamnosys_nonmanual> or <hamnosys_manual>");
    }
  }
  if (!have_manual) fail_at(ctx.file, sign.line, 0, "sign '" + sign.gloss + "' has no <hamnosys_manual>");
  try {
    sign.manual = parse_hamnosys(sign.symbols, ctx.options);
  } catch (const Error& e) {
    rethrow_with_line(ctx, sign, e);
  }
  return sign;
}

// ---- gestural SiGML -----------------------------------------------------------------------------

std::optional<BasicHandshape> gestural_handshape(std::string_view v) {
  constexpr std::pair<std::string_view, BasicHandshape> table[] = {
      {"fist", BasicHandshape::Fist},           {"flat", BasicHandshape::Flat},
      {"finger2", BasicHandshape::Finger2},     {"finger23", BasicHandshape::Finger23},
      {"finger23spread", BasicHandshape::Finger23Spread}, {"finger2345", BasicHandshape::Finger2345},
      {"pinch12", BasicHandshape::Pinch12},     {"pinchall", BasicHandshape::PinchAll},
      {"pinch12open", BasicHandshape::Pinch12Open}, {"cee12", BasicHandshape::Cee12},
      {"ceeall", BasicHandshape::CeeAll},       {"cee12open", BasicHandshape::Cee12Open}};
  for (const auto& [name, shape] : table)
    if (name == v) return shape;
  return std::nullopt;
}

std::optional<FingerBending> gestural_bending(std::string_view v) {
  constexpr std::pair<std::string_view, FingerBending> table[] = {
      {"bent", FingerBending::Bent},       {"round", FingerBending::Round},
      {"hooked", FingerBending::Hooked},   {"halfbent", FingerBending::HalfBent},
      {"dblbent", FingerBending::DoubleBent}, {"dblhooked", FingerBending::DoubleHooked}};
  for (const auto& [name, bending] : table)
    if (name == v) return bending;
  return std::nullopt;
}

class GesturalReader {
 public:
  GesturalReader(const Context& ctx, SigmlSign& sign) : ctx_(ctx), sign_(sign) {}

  void read(const pugi::xml_node& node) {
    ManualSign segment;
    bool have_manual = false;
    for (const pugi::xml_node& part : node.children()) {
      if (part.type() != pugi::node_element) continue;
      const std::string_view name = part.name();
      if (name == "sign_nonmanual") {
        read_nonmanual(part);
        continue;
      }
      if (name != "sign_manual") fail(part, "unexpected <" + std::string(name) + "> in <hamgestural_sign>");
      have_manual = true;
      if (part.attribute("both_hands").as_bool())
        segment.symmetry.kind = part.attribute("lr_symm").as_bool() ? SymmetryKind::mirrored_lr : SymmetryKind::parallel;
      if (part.attribute("nondominant").as_bool()) segment.nondominant_only = true;
      bool in_posture = true;
      for (const pugi::xml_node& e : part.children()) {
        if (e.type() != pugi::node_element) continue;
        read_manual_element(e, segment, in_posture);
      }
    }
    if (!have_manual) fail(node, "<hamgestural_sign> has no <sign_manual>");
    if (!segment.posture.handshape.dominant) fail(node, "gestural sign has no handconfig with a handshape");
    sign_.manual.segments.push_back(std::move(segment));
  }

 private:
  const Context& ctx_;
  SigmlSign& sign_;

  [[noreturn]] void fail(const pugi::xml_node& n, const std::string& message) const {
    fail_at(ctx_.file, ctx_.line_of(n), 0, "sign '" + sign_.gloss + "': " + message);
  }

  // <sign_nonmanual>: tiers (head_tier, facialexpr_tier, mouthing_tier, ...) of basic elements in
  // sequence, or *_par groups of them performed together.
  void read_nonmanual(const pugi::xml_node& node) {
    for (const pugi::xml_node& tier : node.children()) {
      if (tier.type() != pugi::node_element) continue;
      const std::string_view tier_name = tier.name();
      if (!tier_name.ends_with("_tier")) fail(tier, "unexpected <" + std::string(tier_name) + "> in <sign_nonmanual>: expected a *_tier element");
      std::vector<pugi::xml_node> steps;
      for (const pugi::xml_node& step : tier.children())
        if (step.type() == pugi::node_element) steps.push_back(step);
      for (std::size_t k = 0; k < steps.size(); ++k) {
        const float from = static_cast<float>(k) / static_cast<float>(steps.size());
        const float to = static_cast<float>(k + 1) / static_cast<float>(steps.size());
        if (std::string_view(steps[k].name()).ends_with("_par")) {
          for (const pugi::xml_node& e : steps[k].children())
            if (e.type() == pugi::node_element) read_nonmanual_element(e, from, to);
        } else {
          read_nonmanual_element(steps[k], from, to);
        }
      }
    }
  }

  void read_nonmanual_element(const pugi::xml_node& e, float from, float to) {
    using T = NonManualTier;
    constexpr std::pair<std::string_view, NonManualTier> table[] = {
        {"shoulder_movement", T::shoulder}, {"body_movement", T::body},     {"head_movement", T::head},
        {"eye_gaze", T::eye_gaze},          {"eye_brows", T::eyebrows},     {"eye_lids", T::eyelids},
        {"nose", T::nose},                  {"mouth_gesture", T::mouth_gesture}, {"mouth_picture", T::mouth_picture},
        {"extra_movement", T::extra}};
    const std::string_view name = e.name();
    if (name == "neutral") return;  // the face at rest: nothing to perform
    for (const auto& [element, tier] : table) {
      if (element != name) continue;
      const char* attribute = tier == T::mouth_picture ? "picture" : e.attribute("movement") ? "movement" : "direction";
      if (!e.attribute(attribute)) fail(e, "<" + std::string(name) + "> needs a " + attribute + " attribute");
      sign_.nonmanual.push_back({tier, e.attribute(attribute).value(), ctx_.line_of(e), from, to});
      return;
    }
    fail(e, "unknown non-manual element <" + std::string(name) + ">: expected head_movement, eye_brows, mouth_picture, ...");
  }

  Direction direction(const pugi::xml_node& n, const char* attribute) const {
    const auto d = parse_direction(n.attribute(attribute).value());
    if (!d) fail(n, std::string("bad ") + attribute + " '" + n.attribute(attribute).value() + "': expected a direction code such as u, ol, uol");
    return *d;
  }

  // Applies the attributes of one <handconfig> to a handshape and orientation.
  void read_handconfig(const pugi::xml_node& n, std::optional<Handshape>& hs, std::optional<Orientation>& ori) const {
    if (const auto a = n.attribute("handshape")) {
      const auto basic = gestural_handshape(a.value());
      if (!basic) fail(n, std::string("unknown handshape '") + a.value() + "'");
      hs.emplace();
      hs->form.basic = *basic;
      hs->symbol_index = -1;
    }
    if (const auto a = n.attribute("thumbpos")) {
      if (!hs) fail(n, "thumbpos without a handshape");
      const std::string_view v = a.value();
      hs->form.thumb = v == "out" ? ThumbModifier::Out : v == "across" ? ThumbModifier::Across
                       : v == "open" ? ThumbModifier::Opposed : ThumbModifier::Default;
    }
    if (const auto a = n.attribute("mainbend")) {
      if (!hs) fail(n, "mainbend without a handshape");
      hs->form.bending = gestural_bending(a.value());
      if (!hs->form.bending) fail(n, std::string("unknown mainbend '") + a.value() + "'");
    }
    if (n.attribute("extfidir")) {
      if (!ori) ori.emplace();
      ori->extended_finger = direction(n, "extfidir");
    }
    if (n.attribute("palmor")) {
      if (!ori) ori.emplace();
      ori->palm = direction(n, "palmor");
    }
  }

  std::optional<Proximity> contact(const pugi::xml_node& n) const {
    const std::string_view v = n.attribute("contact").value();
    if (v.empty()) return std::nullopt;
    if (v == "close") return Proximity::close;
    if (v == "touch") return Proximity::touch;
    if (v == "interlock" || v == "interlocked") return Proximity::interlocked;
    if (v == "cross") return Proximity::crossed;
    if (v == "armextended") return Proximity::far;
    if (v == "behind") return Proximity::behind;
    if (v == "brushing") return Proximity::brushing;
    fail(n, "unknown contact '" + std::string(v) + "'");
  }

  void read_manual_element(const pugi::xml_node& e, ManualSign& segment, bool& in_posture) {
    const std::string_view name = e.name();
    Posture& p = segment.posture;
    if (name == "handconfig" && in_posture) {
      read_handconfig(e, p.handshape.dominant, p.orientation.dominant);
    } else if (name == "handconstellation") {
      p.hands_contact = contact(e);
    } else if (name == "location_bodyarm") {
      // SiGML site names are the HamNoSys symbol names without the "ham" prefix.
      const auto symbol = symbol_from_name("ham" + std::string(e.attribute("location").value()));
      const auto site = symbol ? site_of_symbol(*symbol) : std::nullopt;
      if (!site) fail(e, std::string("unknown location '") + e.attribute("location").value() + "'");
      Location loc;
      loc.site = *site;
      loc.symbol_index = -1;
      loc.proximity = contact(e);
      if (in_posture) p.location.dominant = loc;
      else push_motion(segment, to_location(loc));
    } else if (name == "directedmotion") {
      in_posture = false;
      Motion m;
      m.direction = direction(e, "direction");
      push_motion(segment, m);
    } else if (name == "circularmotion") {
      in_posture = false;
      Motion m;
      m.kind = MotionKind::circle;
      m.direction = direction(e, "axis");
      push_motion(segment, m);
    } else if (name == "tgt_motion") {
      in_posture = false;
      Motion m;
      m.kind = MotionKind::replacement;
      for (const pugi::xml_node& c : e.children()) {
        if (c.type() != pugi::node_element) continue;
        const std::string_view cn = c.name();
        if (cn == "changeposture") continue;
        if (cn != "handconfig") fail(c, "unsupported <" + std::string(cn) + "> in <tgt_motion>");
        read_handconfig(c, m.new_handshape, m.new_orientation);
      }
      push_motion(segment, m);
    } else if (name == "rpt_motion") {
      in_posture = false;
      Repetition r;
      const std::string_view repeat = e.attribute("repetition").value();
      r.kind = repeat == "fromstart_several" ? RepetitionKind::from_start_several
               : repeat == "continue" ? RepetitionKind::continued
               : repeat == "reverse" ? RepetitionKind::reversed
                                     : RepetitionKind::from_start;
      Element el;
      el.kind = ElementKind::repetition;
      el.value = r;
      segment.actions.push_back(std::move(el));
    } else {
      fail(e, "unsupported gestural element <" + std::string(name) + ">");
    }
  }

  static Motion to_location(const Location& loc) {
    Motion m;
    m.kind = MotionKind::to_location;
    m.target = loc;
    m.target_contact = loc.proximity;
    return m;
  }

  static void push_motion(ManualSign& segment, Motion m) {
    Element el;
    el.kind = ElementKind::motion;
    el.value = std::move(m);
    segment.actions.push_back(std::move(el));
  }
};

SigmlEntry read_entry(const Context& ctx, const pugi::xml_node& node) {
  SigmlEntry entry;
  entry.gloss = node.attribute("gloss").value();
  entry.line = ctx.line_of(node);
  try {
    if (std::string_view(node.name()) == "hns_sign") {
      entry.sign = read_hns_sign(ctx, node);
    } else {
      SigmlSign sign;
      sign.gloss = entry.gloss;
      sign.line = entry.line;
      sign.gestural = true;
      GesturalReader(ctx, sign).read(node);
      try {
        check_sign_limits(sign.manual);
      } catch (const Error& e) {
        fail_at(ctx.file, sign.line, 0, "sign '" + sign.gloss + "': " + e.message());
      }
      entry.sign = std::move(sign);
    }
  } catch (const Error& e) {
    entry.error = e;
  }
  return entry;
}

}  // namespace

std::string_view nonmanual_tier_name(NonManualTier t) {
  switch (t) {
    case NonManualTier::shoulder: return "shoulder";
    case NonManualTier::body: return "body";
    case NonManualTier::head: return "head";
    case NonManualTier::eye_gaze: return "eye gaze";
    case NonManualTier::eyebrows: return "eyebrows";
    case NonManualTier::eyelids: return "eyelids";
    case NonManualTier::nose: return "nose";
    case NonManualTier::cheeks: return "cheeks";
    case NonManualTier::mouth_gesture: return "mouth gesture";
    case NonManualTier::mouth_picture: return "mouth picture";
    case NonManualTier::extra: return "extra";
  }
  return "non-manual";
}

std::vector<SigmlEntry> read_sigml_entries(std::string_view xml, std::string_view file_name, const ParseOptions& options) {
  const LineIndex lines(xml);
  pugi::xml_document doc;
  const pugi::xml_parse_result result = doc.load_buffer(xml.data(), xml.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!result)
    fail_at(file_name, lines.line(result.offset), lines.column(result.offset),
            std::string("malformed XML: ") + result.description());
  const Context ctx{file_name, lines, options};
  const pugi::xml_node root = doc.document_element();
  const std::string_view root_name = root.name();
  std::vector<SigmlEntry> entries;
  auto is_sign = [](std::string_view n) { return n == "hns_sign" || n == "hamgestural_sign"; };
  if (is_sign(root_name)) {
    entries.push_back(read_entry(ctx, root));
    return entries;
  }
  if (root_name != "sigml")
    fail_at(file_name, ctx.line_of(root), 0, "root element <" + std::string(root_name) + ">: expected <sigml>");
  for (const pugi::xml_node& n : root.children()) {
    if (n.type() != pugi::node_element) continue;
    if (!is_sign(n.name()))
      fail_at(file_name, ctx.line_of(n), 0,
              std::string("unexpected <") + n.name() + "> in <sigml>: expected <hns_sign> or <hamgestural_sign>");
    entries.push_back(read_entry(ctx, n));
  }
  return entries;
}

std::vector<SigmlSign> read_sigml(std::string_view xml, std::string_view file_name, const ParseOptions& options) {
  std::vector<SigmlSign> signs;
  for (SigmlEntry& e : read_sigml_entries(xml, file_name, options)) {
    if (!e.sign) throw *e.error;
    signs.push_back(std::move(*e.sign));
  }
  return signs;
}

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open " + path);
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw Error("cannot read " + path);
  if (static_cast<std::size_t>(size) > max_bytes)
    throw Error(path + ": file too large (" + std::to_string(size) + " bytes, limit " + std::to_string(max_bytes) + ")");
  in.seekg(0);
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), size);
  if (!in) throw Error("cannot read " + path);
  return text;
}

}  // namespace gestura::sign
