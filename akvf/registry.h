#pragma once
// Name-to-factory registries: the command line and the experiment runner
// pick energies, preconditioners and line searches by name.
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "akvf/error.h"

namespace akvf {

template <class Product, class... Args>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Product>(Args...)>;

  explicit Registry(std::string kind) : kind_(std::move(kind)) {}

  // OptionsError when `name` is taken or empty. `tags` are facts about the
  // entry that callers ask for by name (has_tag), instead of comparing names.
  void add(const std::string& name, const std::string& description, Factory factory, std::set<std::string> tags = {}) {
    if (name.empty()) throw OptionsError("a " + kind_ + " needs a name");
    if (contains(name)) throw OptionsError(kind_ + " '" + name + "' is already registered");
    tags_[name] = std::move(tags);
    entries_.push_back({name, description});
    factories_[name] = std::move(factory);
  }

  bool contains(const std::string& name) const { return factories_.count(name) > 0; }
  bool has_tag(const std::string& name, const std::string& tag) const {
    const auto it = tags_.find(name);
    return it != tags_.end() && it->second.count(tag) > 0;
  }

  // Throws OptionsError listing the valid names when `name` is unknown.
  void require(const std::string& name) const {
    if (!contains(name)) throw OptionsError("unknown " + kind_ + " '" + name + "' (valid: " + names() + ")");
  }

  std::unique_ptr<Product> create(const std::string& name, Args... args) const {
    require(name);
    return factories_.at(name)(std::forward<Args>(args)...);
  }

  std::string names() const {
    std::string list;
    for (const auto& entry : entries_) list += (list.empty() ? "" : ", ") + entry.first;
    return list;
  }

  // (name, one-line description) in registration order.
  const std::vector<std::pair<std::string, std::string>>& entries() const { return entries_; }

 private:
  std::string kind_;
  std::vector<std::pair<std::string, std::string>> entries_;
  std::map<std::string, Factory> factories_;
  std::map<std::string, std::set<std::string>> tags_;
};

}  // namespace akvf
