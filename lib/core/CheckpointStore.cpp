#include "core/CheckpointStore.hpp"

namespace mfwave {
namespace {

std::shared_ptr<CheckpointStore>& installed() {
  static std::shared_ptr<CheckpointStore> store;
  return store;
}

}  // namespace

void installCheckpointStore(std::shared_ptr<CheckpointStore> store) { installed() = std::move(store); }
CheckpointStore* checkpointStore() { return installed().get(); }

}  // namespace mfwave
