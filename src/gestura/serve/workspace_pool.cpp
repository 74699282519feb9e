#include "gestura/serve/workspace_pool.hpp"

namespace gestura::serve {

WorkspacePool::WorkspacePool(int size, const std::string& citation_store) {
  for (int i = 0; i < size; ++i) {
    all_.push_back(std::make_unique<app::Workspace>(citation_store));
    free_.push_back(all_.back().get());
  }
}

WorkspacePool::Lease WorkspacePool::acquire() {
  std::unique_lock lock(mutex_);
  returned_.wait(lock, [&] { return !free_.empty(); });
  app::Workspace* w = free_.back();
  free_.pop_back();
  return Lease(*this, w);
}

void WorkspacePool::give_back(app::Workspace* workspace) {
  {
    std::lock_guard lock(mutex_);
    free_.push_back(workspace);
  }
  returned_.notify_one();
}

}  // namespace gestura::serve
