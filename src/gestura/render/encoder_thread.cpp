#include "gestura/render/encoder_thread.hpp"

#include <utility>

namespace gestura {

EncoderThread::EncoderThread(VideoWriter& writer) : writer_(&writer), thread_([this] { run(); }) {}

EncoderThread::~EncoderThread() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void EncoderThread::run() {
  Image working;
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return has_pending_ || stopping_; });
    if (stopping_) return;
    std::swap(working, pending_);
    has_pending_ = false, busy_ = true;
    lock.unlock();
    std::exception_ptr error;
    try {
      writer_->write(working);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    busy_ = false;
    if (error && !error_) error_ = error;
    changed_.notify_all();
  }
}

void EncoderThread::wait_idle(std::unique_lock<std::mutex>& lock) {
  changed_.wait(lock, [&] { return !has_pending_ && !busy_; });
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void EncoderThread::submit(Image& frame) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return !has_pending_; });  // the encoder may still be busy with the previous one
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  std::swap(pending_, frame);
  has_pending_ = true;
  changed_.notify_all();
}

void EncoderThread::finish() {
  std::unique_lock lock(mutex_);
  wait_idle(lock);
  writer_->finish();
}

}  // namespace gestura
