#include "gestura/io/openpose_json.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/io/json_excerpt.hpp"

namespace gestura {

std::vector<std::string> openpose_json_frames(const Skeleton& skeleton, const Clip& clip, float fps,
                                              const PinholeCamera& camera) {
  const Keypoints body = compute_keypoints(skeleton, clip, fps, KeypointSet::Body25);
  const Keypoints left = compute_keypoints(skeleton, clip, fps, KeypointSet::LeftHand);
  const Keypoints right = compute_keypoints(skeleton, clip, fps, KeypointSet::RightHand);
  auto flat = [&](const Keypoints& k, int frame) {
    nlohmann::json values = nlohmann::json::array();
    for (int i = 0; i < k.count; ++i) {
      const std::size_t at = static_cast<std::size_t>(frame) * static_cast<std::size_t>(k.count) + static_cast<std::size_t>(i);
      const vec3 px = camera.project(k.positions[at]);
      const bool seen = k.confidence[at] > 0.0f && px.z > 0.0f;
      values.push_back(seen ? px.x : 0.0f);
      values.push_back(seen ? px.y : 0.0f);
      values.push_back(seen ? k.confidence[at] : 0.0f);
    }
    return values;
  };
  std::vector<std::string> frames;
  for (int f = 0; f < body.frames; ++f) {
    nlohmann::json person = {{"person_id", {-1}},
                             {"pose_keypoints_2d", flat(body, f)},
                             {"face_keypoints_2d", nlohmann::json::array()},
                             {"hand_left_keypoints_2d", flat(left, f)},
                             {"hand_right_keypoints_2d", flat(right, f)},
                             {"pose_keypoints_3d", nlohmann::json::array()},
                             {"face_keypoints_3d", nlohmann::json::array()},
                             {"hand_left_keypoints_3d", nlohmann::json::array()},
                             {"hand_right_keypoints_3d", nlohmann::json::array()}};
    const nlohmann::json doc = {{"version", 1.3}, {"people", nlohmann::json::array({person})}};
    frames.push_back(doc.dump());
  }
  return frames;
}

std::vector<std::string> save_openpose_json(const std::string& path, const Skeleton& skeleton, const Clip& clip,
                                            float fps, const PinholeCamera& camera) {
  const std::vector<std::string> frames = openpose_json_frames(skeleton, clip, fps, camera);
  const std::filesystem::path base(path);
  // All frames or none: a failure half-way must not leave a shorter sequence that looks complete.
  StagedFileGroup group(base.parent_path().string(), base.stem().string());
  for (std::size_t f = 0; f < frames.size(); ++f) {
    char number[48];
    std::snprintf(number, sizeof number, "_%012zu_keypoints.json", f);
    group.write(base.stem().string() + number, frames[f]);
  }
  return group.commit();
}

}  // namespace gestura

// ---- reading ----------------------------------------------------------------------------------

namespace gestura {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& source, const std::string& where, const std::string& what) {
  throw Error(SourceLocation{source}, (where.empty() ? "" : where + ": ") + what);
}

std::vector<float> keypoint_array(const json& person, const char* key, int per_point, const std::string& source,
                                  const std::string& where) {
  std::vector<float> out;
  const auto it = person.find(key);
  if (it == person.end() || it->is_null()) return out;
  const std::string place = where + "." + key;
  if (!it->is_array()) fail(source, place, "not an array of numbers");
  if (it->size() > kMaxOpenPoseNumbers)
    fail(source, place, std::to_string(it->size()) + " numbers, more than the limit of " +
                            std::to_string(kMaxOpenPoseNumbers) + " (kMaxOpenPoseNumbers)");
  if (it->size() % static_cast<std::size_t>(per_point) != 0)
    fail(source, place, std::to_string(it->size()) + " numbers, not whole " +
                            (per_point == 3 ? "x, y, confidence triples" : "x, y, z, confidence quadruples"));
  out.reserve(it->size());
  for (std::size_t i = 0; i < it->size(); ++i) {
    const json& v = (*it)[i];
    if (!v.is_number()) fail(source, place + "[" + std::to_string(i) + "]", "not a number: " + json_excerpt(v));
    const double d = v.get<double>();
    if (!std::isfinite(d) || std::fabs(d) > 1e30)
      fail(source, place + "[" + std::to_string(i) + "]", "not a finite number within ±1e30");
    out.push_back(static_cast<float>(d));
  }
  return out;
}

// "NAME_000000000012_keypoints.json" → 12; -1 when the name is not of that form.
long long frame_number(const std::string& file_name) {
  static const std::string suffix = "_keypoints.json";
  if (file_name.size() <= suffix.size() || file_name.compare(file_name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return -1;
  const std::size_t end = file_name.size() - suffix.size();
  std::size_t begin = end;
  while (begin > 0 && std::isdigit(static_cast<unsigned char>(file_name[begin - 1]))) --begin;
  if (begin == end || end - begin > 15 || begin == 0 || file_name[begin - 1] != '_') return -1;
  return std::stoll(file_name.substr(begin, end - begin));
}

std::string read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(SourceLocation{path}, "cannot open file");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw Error(SourceLocation{path}, "cannot read the file");
  if (static_cast<std::uint64_t>(size) > kMaxOpenPoseFileBytes)
    throw Error(SourceLocation{path}, "the file is larger than the limit of " + std::to_string(kMaxOpenPoseFileBytes) +
                                          " bytes for one OpenPose frame (kMaxOpenPoseFileBytes)");
  in.seekg(0);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), size);
  if (!in) throw Error(SourceLocation{path}, "cannot read the file");
  return bytes;
}

}  // namespace

OpenPoseFrame read_openpose_frame(std::string_view text, const std::string& source) {
  if (text.size() > kMaxOpenPoseFileBytes)
    fail(source, "", "larger than the limit of " + std::to_string(kMaxOpenPoseFileBytes) +
                         " bytes for one OpenPose frame (kMaxOpenPoseFileBytes)");
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    // Locate the byte nlohmann names as a line and column.
    const std::size_t at = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    int line = 1, column = 1;
    for (std::size_t i = 0; i < at; ++i) {
      if (text[i] == '\n') ++line, column = 1;
      else ++column;
    }
    throw Error(SourceLocation{source, line, column}, "not JSON: " + std::string(e.what()).substr(0, 160));
  } catch (const json::exception& e) {  // e.g. a number too large for a double
    throw Error(SourceLocation{source}, "not readable JSON: " + std::string(e.what()).substr(0, 160));
  }
  if (!doc.is_object()) fail(source, "", "an OpenPose frame is a JSON object with a \"people\" array");
  const auto people = doc.find("people");
  if (people == doc.end()) fail(source, "", "no \"people\" array: not OpenPose keypoints");
  if (!people->is_array()) fail(source, "people", "not an array");
  if (people->size() > kMaxOpenPosePeople)
    fail(source, "people", std::to_string(people->size()) + " people, more than the limit of " +
                               std::to_string(kMaxOpenPosePeople) + " (kMaxOpenPosePeople)");
  OpenPoseFrame frame;
  for (std::size_t p = 0; p < people->size(); ++p) {
    const json& person = (*people)[p];
    const std::string where = "people[" + std::to_string(p) + "]";
    if (!person.is_object()) fail(source, where, "not an object");
    OpenPosePerson out;
    if (const auto id = person.find("person_id"); id != person.end()) {
      // OpenPose writes [-1]; a bare number is accepted too.
      const json& value = id->is_array() && id->size() == 1 ? (*id)[0] : *id;
      if (!value.is_number_integer() || value.get<long long>() < -1 || value.get<long long>() > 1000000000)
        fail(source, where + ".person_id", "not a whole number (or [number]) from -1");
      out.person_id = static_cast<int>(value.get<long long>());
    }
    out.pose_2d = keypoint_array(person, "pose_keypoints_2d", 3, source, where);
    out.face_2d = keypoint_array(person, "face_keypoints_2d", 3, source, where);
    out.hand_left_2d = keypoint_array(person, "hand_left_keypoints_2d", 3, source, where);
    out.hand_right_2d = keypoint_array(person, "hand_right_keypoints_2d", 3, source, where);
    out.pose_3d = keypoint_array(person, "pose_keypoints_3d", 4, source, where);
    out.face_3d = keypoint_array(person, "face_keypoints_3d", 4, source, where);
    out.hand_left_3d = keypoint_array(person, "hand_left_keypoints_3d", 4, source, where);
    out.hand_right_3d = keypoint_array(person, "hand_right_keypoints_3d", 4, source, where);
    frame.people.push_back(std::move(out));
  }
  return frame;
}

OpenPoseSequence load_openpose_json(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<std::pair<long long, std::string>> numbered;
  auto collect = [&](const fs::path& directory, const std::string& prefix) {
    for (const auto& entry : fs::directory_iterator(directory, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.compare(0, prefix.size(), prefix) != 0) continue;
      const long long number = frame_number(name);
      if (number < 0) continue;
      // NAME_<digits>_keypoints.json: only digits between the prefix and the suffix.
      if (!prefix.empty()) {
        const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - 15);
        if (middle.empty() || middle.find_first_not_of("0123456789") != std::string::npos) continue;
      }
      if (numbered.size() >= kMaxOpenPoseFrames)
        throw Error(SourceLocation{path}, "more than " + std::to_string(kMaxOpenPoseFrames) +
                                              " frames (kMaxOpenPoseFrames)");
      numbered.emplace_back(number, entry.path().string());
    }
    if (ec) throw Error(SourceLocation{directory.string()}, "cannot list the folder: " + ec.message());
  };
  OpenPoseSequence sequence;
  if (fs::is_directory(path, ec)) {
    collect(path, "");
  } else if (fs::exists(path, ec)) {
    sequence.files.push_back(path);
    sequence.frames.push_back(read_openpose_frame(read_whole_file(path), path));
    return sequence;
  } else {
    const fs::path base(path);
    const fs::path directory = base.parent_path().empty() ? fs::path(".") : base.parent_path();
    collect(directory, base.stem().string() + "_");
  }
  if (numbered.empty())
    throw Error(SourceLocation{path}, "no OpenPose keypoint files (NAME_<frame>_keypoints.json) found");
  std::sort(numbered.begin(), numbered.end());
  for (std::size_t i = 0; i < numbered.size(); ++i) {
    if (numbered[i].first != static_cast<long long>(i))
      throw Error(SourceLocation{numbered[i].second},
                  i > 0 && numbered[i].first == numbered[i - 1].first
                      ? "frame " + std::to_string(numbered[i].first) + " appears twice"
                      : "frame " + std::to_string(i) + " is missing (the frames must run 0, 1, 2, ...)");
    sequence.files.push_back(numbered[i].second);
  }
  for (const std::string& file : sequence.files) sequence.frames.push_back(read_openpose_frame(read_whole_file(file), file));
  return sequence;
}

}  // namespace gestura
