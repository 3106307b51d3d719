#pragma once
// A map that forgets what was used least recently once it holds more than an entry or a
// byte budget, so a worker that runs thousands of variants keeps a bounded working set
// (compiled programs, LUTs, shader texts) instead of growing until its allocations fail.
// The newest entry is never evicted, so a reference returned by put() stays valid until
// the next put(); find() moves an entry to the front.
#include <cstddef>
#include <list>
#include <string>
#include <unordered_map>
#include <utility>

namespace shaderbed {

template <typename Value>
class LruCache {
 public:
  LruCache(size_t max_entries, size_t max_bytes) : max_entries_(max_entries), max_bytes_(max_bytes) {}

  // The entry, now the most recently used; nullptr when absent.
  Value* find(const std::string& key) {
    const auto it = index_.find(key);
    if (it == index_.end()) return nullptr;
    entries_.splice(entries_.begin(), entries_, it->second);
    return &it->second->value;
  }

  // Adds (or replaces) `key`, counted as `bytes`, then evicts from the least recently used
  // end until both budgets hold again (or only this entry is left).
  Value& put(const std::string& key, Value value, size_t bytes) {
    if (const auto it = index_.find(key); it != index_.end()) {
      bytes_ -= it->second->bytes;
      entries_.erase(it->second);
      index_.erase(it);
    }
    entries_.push_front(Entry{key, std::move(value), bytes});
    index_[key] = entries_.begin();
    bytes_ += bytes;
    while (entries_.size() > 1 && (entries_.size() > max_entries_ || bytes_ > max_bytes_)) {
      const Entry& last = entries_.back();
      bytes_ -= last.bytes;
      index_.erase(last.key);
      entries_.pop_back();
      ++evictions_;
    }
    return entries_.front().value;
  }

  size_t size() const { return entries_.size(); }
  size_t bytes() const { return bytes_; }
  size_t evictions() const { return evictions_; }

 private:
  struct Entry {
    std::string key;
    Value value;
    size_t bytes = 0;
  };
  size_t max_entries_, max_bytes_;
  std::list<Entry> entries_;   // most recently used first
  std::unordered_map<std::string, typename std::list<Entry>::iterator> index_;
  size_t bytes_ = 0;
  size_t evictions_ = 0;
};

}  // namespace shaderbed
