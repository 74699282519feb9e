#pragma once
// Encoding on a second thread, so colour conversion and compression of frame i overlap the
// drawing of frame i+1 (on llvmpipe both are CPU work; the overlap fills the gaps each leaves,
// e.g. the GL's single-threaded vertex and setup stages, and the encoder's serial parts).
//
// One frame is in flight at most: submit() hands the frame over (swapping buffers, no copy) and
// waits only while the previous one is still being encoded. An encoder error is rethrown by the
// next submit() or by finish(). Without finish() the video is abandoned (no file left).
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "gestura/render/image.hpp"
#include "gestura/render/video_writer.hpp"

namespace gestura {

class EncoderThread {
 public:
  explicit EncoderThread(VideoWriter& writer);  // contract: `writer` outlives this
  ~EncoderThread();                             // stops the thread; a pending frame is dropped
  EncoderThread(const EncoderThread&) = delete;
  EncoderThread& operator=(const EncoderThread&) = delete;

  // Takes `frame`'s pixels (leaving it holding a free buffer of any size).
  void submit(Image& frame);
  // Waits for the last frame, then finishes the writer. Rethrows an encoder error.
  void finish();

 private:
  void run();
  void wait_idle(std::unique_lock<std::mutex>& lock);
  VideoWriter* writer_;
  std::mutex mutex_;
  std::condition_variable changed_;
  Image pending_;
  bool has_pending_ = false, busy_ = false, stopping_ = false;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace gestura
