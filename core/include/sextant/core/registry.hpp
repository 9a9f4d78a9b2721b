#pragma once
// A runtime registry by name (matchers, samplers, filters, datasets), so a YAML file chooses
// `method: mlndt` without recompiling. Each module owns one registry instance and fills it in
// an explicit function (no static initialisers, which shared libraries may drop).
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace sextant {

template <class Product, class... Args>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Product>(Args...)>;

  explicit Registry(std::string kind) : kind_(std::move(kind)) {}

  void add(const std::string& name, std::string description, Factory factory) {
    entries_[name] = Entry{std::move(description), std::move(factory)};
  }
  bool contains(const std::string& name) const { return entries_.count(name) > 0; }

  /// Throws std::invalid_argument naming the known entries when `name` is unknown.
  std::unique_ptr<Product> create(const std::string& name, Args... args) const {
    const auto it = entries_.find(name);
    if (it == entries_.end()) throw std::invalid_argument(unknown(name));
    return it->second.factory(std::forward<Args>(args)...);
  }

  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& [name, entry] : entries_) out.push_back(name);
    return out;
  }
  const std::string& description(const std::string& name) const { return entries_.at(name).description; }

  std::string unknown(const std::string& name) const {
    std::string msg = "unknown " + kind_ + " '" + name + "' (known:";
    for (const auto& [known, entry] : entries_) msg += " " + known;
    return msg + ")";
  }

 private:
  struct Entry {
    std::string description;
    Factory factory;
  };
  std::string kind_;
  std::map<std::string, Entry> entries_;
};

}  // namespace sextant
