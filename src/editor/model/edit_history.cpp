#include "editor/model/edit_history.h"

namespace kinema {

void EditHistory::push(EditRecord record) {
  entries_.resize(position_);  // a new edit drops the redo tail
  entries_.push_back(std::move(record));
  if (capacity_ > 0 && static_cast<int>(entries_.size()) > capacity_) {
    entries_.erase(entries_.begin());
    ++dropped_;
  }
  position_ = size();
}

const EditRecord* EditHistory::stepBack() {
  if (!canUndo()) return nullptr;
  return &entries_[--position_];
}

const EditRecord* EditHistory::stepForward() {
  if (!canRedo()) return nullptr;
  return &entries_[position_++];
}

void EditHistory::clear() {
  entries_.clear();
  position_ = 0;
  dropped_ = 0;
}

}  // namespace kinema
