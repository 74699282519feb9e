#pragma once
// Animated output through libavcodec/libavformat: MP4 (H.264 via libx264), WebM (VP9 via
// libvpx-vp9) and GIF (ffmpeg's gif encoder fed with our own palette: a fixed 6×7×6 colour cube
// with ordered dithering, plus the first frame's most frequent colours — the background — exact). Frame i gets timestamp i / fps exactly, so the file has exactly the
// frames written at exactly the frame rate asked for (GIF stores delays in 1/100 s, so its rate is
// only exact for fps dividing 100). Staged: the target appears only when finish() succeeds.
#include <memory>
#include <string>

#include "gestura/render/image.hpp"

namespace gestura {

enum class VideoFormat : std::uint8_t { Gif, Mp4, WebM };

// From the file name's extension (.gif, .mp4, .webm); nullopt-like failure throws gestura::Error.
VideoFormat video_format_of(const std::string& path);
bool is_video_path(const std::string& path);

class VideoWriter {
 public:
  // Throws gestura::Error for an unwritable path, a missing encoder or sizes the codec refuses
  // (H.264 and VP9 in 4:2:0 need even width and height).
  VideoWriter(const std::string& path, int width, int height, int fps);
  ~VideoWriter();  // without finish(): discards everything, leaves no file
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  void write(const Image& frame);  // frame must have the writer's size
  void finish();                   // flushes the encoder, writes the trailer, renames into place
  int frames_written() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace gestura
