#include "gestura/render/video_writer.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <vector>
#include <optional>

#include "gestura/core/error.hpp"
#include "gestura/core/output_limits.hpp"
#include "gestura/core/staged_file.hpp"

namespace gestura {
namespace {

std::string extension(const std::string& path) {
  const auto dot = path.rfind('.');
  if (dot == std::string::npos) return "";
  std::string e = path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

std::string av_message(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

// The GIF palette: 6 levels of red, 7 of green, 6 of blue (252 colours).
constexpr int kRed = 6, kGreen = 7, kBlue = 6;
// 4×4 Bayer matrix, thresholds in (0, 1).
constexpr float kBayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};

std::uint8_t quantise(std::uint8_t value, int levels, float threshold) {
  const float scaled = static_cast<float>(value) / 255.0f * static_cast<float>(levels - 1);
  return static_cast<std::uint8_t>(std::min<float>(static_cast<float>(levels - 1), std::floor(scaled + threshold)));
}

}  // namespace

VideoFormat video_format_of(const std::string& path) {
  const std::string e = extension(path);
  if (e == "gif") return VideoFormat::Gif;
  if (e == "mp4") return VideoFormat::Mp4;
  if (e == "webm") return VideoFormat::WebM;
  throw Error("cannot write " + path + ": unknown video type '." + e + "' (use .gif, .mp4 or .webm)");
}

bool is_video_path(const std::string& path) {
  const std::string e = extension(path);
  return e == "gif" || e == "mp4" || e == "webm";
}

struct VideoWriter::State {
  std::optional<StagedFile> file;
  VideoFormat format{};
  int width = 0, height = 0, frames = 0;
  AVFormatContext* container = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scaler = nullptr;
  bool finished = false;
  // GIF: the 6×7×6 cube plus, in the last 4 entries, the most frequent exact colours of the first
  // frame (the background above all), which are then drawn flat instead of dithered.
  std::uint32_t palette[256] = {};
  std::uint32_t exact[256 - kRed * kGreen * kBlue] = {};
  int exact_count = 0;

  void choose_exact_colours(const Image& image) {
    std::unordered_map<std::uint32_t, int> counts;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4 * 7)  // a sample is plenty
      ++counts[static_cast<std::uint32_t>(image.rgba[i]) << 16 | static_cast<std::uint32_t>(image.rgba[i + 1]) << 8 |
               image.rgba[i + 2]];
    std::vector<std::pair<int, std::uint32_t>> ranked;
    for (const auto& [colour, n] : counts) ranked.emplace_back(n, colour);
    std::sort(ranked.rbegin(), ranked.rend());
    exact_count = static_cast<int>(std::min(ranked.size(), std::size(exact)));
    for (int k = 0; k < exact_count; ++k) {
      exact[k] = ranked[static_cast<std::size_t>(k)].second;
      palette[kRed * kGreen * kBlue + k] = 0xff000000u | exact[k];
    }
  }

  ~State() {
    sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (container) {
      if (container->pb) avio_closep(&container->pb);
      avformat_free_context(container);
    }
  }

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw Error("cannot write " + file->target() + ": " + what + (code < 0 ? " (" + av_message(code) + ")" : ""));
  }

  // The muxer buffers its writes and keeps the first error in the I/O context; a full disk shows
  // there before any call returns it.
  void check_written() const {
    if (container->pb->error < 0) fail("writing failed", container->pb->error);
    check_output_size(static_cast<std::uint64_t>(std::max<std::int64_t>(0, avio_tell(container->pb))),
                      "cannot write " + file->target());
  }

  // Sends one frame (or nullptr to flush) and writes every packet the encoder returns.
  void encode(AVFrame* input) {
    int rc = avcodec_send_frame(codec, input);
    if (rc < 0) fail("encoding failed", rc);
    while ((rc = avcodec_receive_packet(codec, packet)) >= 0) {
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(container, packet);
      if (rc < 0) fail("writing a packet failed", rc);
      check_written();
    }
    if (rc != AVERROR(EAGAIN) && rc != AVERROR_EOF) fail("encoding failed", rc);
  }
};

VideoWriter::VideoWriter(const std::string& path, int width, int height, int fps) : state_(std::make_unique<State>()) {
  State& s = *state_;
  av_log_set_level(AV_LOG_ERROR);  // encoders chat on stderr at the default level
  s.format = video_format_of(path);
  s.width = width, s.height = height;
  if (s.format != VideoFormat::Gif && (width % 2 != 0 || height % 2 != 0))
    throw Error("cannot write " + path + ": MP4/WebM need an even width and height, got " + std::to_string(width) + "x" +
                std::to_string(height));
  s.file.emplace(path);
  const char* muxer = s.format == VideoFormat::Gif ? "gif" : s.format == VideoFormat::Mp4 ? "mp4" : "webm";
  const char* encoder = s.format == VideoFormat::Gif ? "gif" : s.format == VideoFormat::Mp4 ? "libx264" : "libvpx-vp9";
  int rc = avformat_alloc_output_context2(&s.container, nullptr, muxer, s.file->temp_path().c_str());
  if (rc < 0) s.fail(std::string("no ") + muxer + " muxer", rc);
  const AVCodec* codec = avcodec_find_encoder_by_name(encoder);
  if (codec == nullptr) s.fail(std::string("this ffmpeg has no ") + encoder + " encoder", 0);
  s.codec = avcodec_alloc_context3(codec);
  s.codec->width = width;
  s.codec->height = height;
  s.codec->time_base = AVRational{1, fps};
  s.codec->framerate = AVRational{fps, 1};
  s.codec->pix_fmt = s.format == VideoFormat::Gif ? AV_PIX_FMT_PAL8 : AV_PIX_FMT_YUV420P;
  s.codec->gop_size = 2 * fps;
  s.codec->thread_count = 0;  // let the codec pick (one per core)
  if (s.format == VideoFormat::Mp4) {
    // One x264 thread: frames come from the renderer one at a time (render_to_file encodes on its
    // own thread beside the drawing), and x264's frame threads and lookahead thread cost ~13 % more
    // CPU for the same bytes (bench R1); the file is the same size.
    s.codec->thread_count = 1;
    av_opt_set(s.codec->priv_data, "preset", "superfast", 0);
    av_opt_set(s.codec->priv_data, "crf", "20", 0);
  } else if (s.format == VideoFormat::WebM) {
    s.codec->bit_rate = 0;
    av_opt_set(s.codec->priv_data, "deadline", "realtime", 0);
    av_opt_set(s.codec->priv_data, "cpu-used", "8", 0);
    av_opt_set(s.codec->priv_data, "row-mt", "1", 0);
    av_opt_set(s.codec->priv_data, "crf", "32", 0);
  }
  // The WebM muxer otherwise writes a random segment UID: the same request would give different bytes
  // (render workers sharing jobs check their videos against a one-process render byte for byte).
  if (s.format == VideoFormat::WebM) s.container->flags |= AVFMT_FLAG_BITEXACT;
  if (s.container->oformat->flags & AVFMT_GLOBALHEADER) s.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  rc = avcodec_open2(s.codec, codec, nullptr);
  if (rc < 0) s.fail(std::string("cannot open the ") + encoder + " encoder", rc);
  s.stream = avformat_new_stream(s.container, nullptr);
  if (s.stream == nullptr) s.fail("cannot add a stream", 0);
  s.stream->time_base = s.codec->time_base;
  s.stream->avg_frame_rate = s.codec->framerate;
  s.stream->r_frame_rate = s.codec->framerate;
  rc = avcodec_parameters_from_context(s.stream->codecpar, s.codec);
  if (rc < 0) s.fail("cannot set stream parameters", rc);
  rc = avio_open(&s.container->pb, s.file->temp_path().c_str(), AVIO_FLAG_WRITE);
  if (rc < 0) s.fail("cannot open the file", rc);
  rc = avformat_write_header(s.container, nullptr);
  if (rc < 0) s.fail("cannot write the header", rc);

  s.frame = av_frame_alloc();
  s.packet = av_packet_alloc();
  s.frame->format = s.codec->pix_fmt;
  s.frame->width = width;
  s.frame->height = height;
  rc = av_frame_get_buffer(s.frame, 0);
  if (rc < 0) s.fail("cannot allocate a frame", rc);
  if (s.format == VideoFormat::Gif) {
    for (int i = 0; i < kRed * kGreen * kBlue; ++i) {
      const int r = i / (kGreen * kBlue), g = i / kBlue % kGreen, b = i % kBlue;
      s.palette[i] = 0xff000000u | static_cast<std::uint32_t>(r * 255 / (kRed - 1)) << 16 |
                     static_cast<std::uint32_t>(g * 255 / (kGreen - 1)) << 8 | static_cast<std::uint32_t>(b * 255 / (kBlue - 1));
    }
  } else {
    s.scaler = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P, SWS_BILINEAR,
                              nullptr, nullptr, nullptr);
    if (s.scaler == nullptr) s.fail("cannot set up colour conversion", 0);
  }
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::write(const Image& image) {
  State& s = *state_;
  if (s.finished) throw Error("video: write() after finish()");
  if (image.width != s.width || image.height != s.height) throw Error("video: frame size differs from the video's");
  const int rc = av_frame_make_writable(s.frame);
  if (rc < 0) s.fail("cannot reuse the frame buffer", rc);
  if (s.format == VideoFormat::Gif) {
    if (s.frames == 0) s.choose_exact_colours(image);
    std::memcpy(s.frame->data[1], s.palette, sizeof s.palette);
    for (int y = 0; y < s.height; ++y) {
      std::uint8_t* row = s.frame->data[0] + static_cast<std::ptrdiff_t>(y) * s.frame->linesize[0];
      for (int x = 0; x < s.width; ++x) {
        const std::uint8_t* p = image.pixel(x, y);
        const std::uint32_t colour = static_cast<std::uint32_t>(p[0]) << 16 | static_cast<std::uint32_t>(p[1]) << 8 | p[2];
        int k = 0;
        while (k < s.exact_count && s.exact[k] != colour) ++k;
        if (k < s.exact_count) {
          row[x] = static_cast<std::uint8_t>(kRed * kGreen * kBlue + k);
          continue;
        }
        const float t = (kBayer[y & 3][x & 3] + 0.5f) / 16.0f;
        row[x] = static_cast<std::uint8_t>((quantise(p[0], kRed, t) * kGreen + quantise(p[1], kGreen, t)) * kBlue +
                                           quantise(p[2], kBlue, t));
      }
    }
  } else {
    const std::uint8_t* source[1] = {image.rgba.data()};
    const int stride[1] = {image.width * 4};
    sws_scale(s.scaler, source, stride, 0, s.height, s.frame->data, s.frame->linesize);
  }
  s.frame->pts = s.frames++;
  s.encode(s.frame);
}

void VideoWriter::finish() {
  State& s = *state_;
  if (s.finished) return;
  s.encode(nullptr);
  int rc = av_write_trailer(s.container);
  if (rc < 0) s.fail("cannot finish the file", rc);
  avio_flush(s.container->pb);
  s.check_written();
  rc = avio_closep(&s.container->pb);
  if (rc < 0) s.fail("cannot finish the file", rc);
  s.finished = true;
  s.file->commit();
}

int VideoWriter::frames_written() const { return state_->frames; }

}  // namespace gestura
