#pragma once
// Workspaces for concurrent requests: one per request running at once. A workspace's lexicon is
// a SQLite connection with its prepared statements and its signer keeps caches, so two requests
// never share one; each request leases a workspace for its length (blocking while all are busy).
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "gestura/app/workspace.hpp"

namespace gestura::serve {

class WorkspacePool {
 public:
  // `citation_store`: where every workspace keeps solved signs (app/workspace.hpp); empty: memory only.
  explicit WorkspacePool(int size, const std::string& citation_store = {});

  class Lease {
   public:
    Lease(WorkspacePool& pool, app::Workspace* workspace) : pool_(&pool), workspace_(workspace) {}
    Lease(Lease&& other) noexcept : pool_(other.pool_), workspace_(other.workspace_) { other.workspace_ = nullptr; }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    Lease& operator=(Lease&&) = delete;
    ~Lease() {
      if (workspace_) pool_->give_back(workspace_);
    }
    app::Workspace& operator*() const { return *workspace_; }
    app::Workspace* get() const { return workspace_; }
    app::Workspace* operator->() const { return workspace_; }

   private:
    WorkspacePool* pool_;
    app::Workspace* workspace_;
  };

  Lease acquire();
  int size() const { return static_cast<int>(all_.size()); }

 private:
  void give_back(app::Workspace* workspace);
  std::vector<std::unique_ptr<app::Workspace>> all_;
  std::vector<app::Workspace*> free_;  // last in, first out: the most recently used (warm) one first
  std::mutex mutex_;
  std::condition_variable returned_;
};

}  // namespace gestura::serve
