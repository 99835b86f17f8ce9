#include "tioa/variables.hpp"

#include <mutex>
#include <unordered_set>

#include "tioa/errors.hpp"

namespace tioa {

namespace {
std::uint8_t bits_for(std::uint64_t codes) {
  std::uint8_t width = 0;
  while (width < 64 && (std::uint64_t{1} << width) < codes)
    ++width;
  return width;
}
} // namespace

Slot VariableInfo::slot() const {
  Slot slot = Slot::bits(offset, width);
  slot.has_bottom = has_bottom;
  slot.lo = lo;
  slot.value_codes = value_codes();
  slot.name = intern(name);
  return slot;
}

std::string VariableInfo::render_code(std::uint64_t code) const {
  if (has_bottom && code == value_codes())
    return "⊥";
  switch (kind) {
  case VariableKind::boolean:
    return code ? "true" : "false";
  case VariableKind::enumeration:
    return code < enum_names.size() ? enum_names[code] : std::to_string(code);
  case VariableKind::set: {
    std::string out;
    for (std::size_t k = 0; k < enum_names.size(); ++k)
      if (code >> k & 1)
        out += (out.empty() ? "" : ", ") + enum_names[k];
    return "{" + out + "}";
  }
  default:
    return std::to_string(lo + static_cast<std::int64_t>(code));
  }
}

const VariableInfo& StateLayout::add(VariableInfo info) {
  if (info.hi < info.lo)
    throw ModelError("variable '" + info.name + "' has an empty domain");
  if (find(info.name))
    throw ModelError("variable '" + info.name + "' is declared twice");
  info.width = bits_for(info.code_count());
  info.offset = bits_;
  bits_ += info.width;
  variables_.push_back(std::move(info));
  return variables_.back();
}

const VariableInfo* StateLayout::find(const std::string& name) const {
  for (const auto& v : variables_)
    if (v.name == name)
      return &v;
  return nullptr;
}

std::uint32_t StateLayout::append(const StateLayout& other, const std::string& prefix) {
  const std::uint32_t base = bits_;
  for (VariableInfo v : other.variables_) {
    v.name = prefix + v.name;
    v.offset += base;
    variables_.push_back(std::move(v));
  }
  bits_ += other.bits_;
  return base;
}

const char* intern(const std::string& name) {
  static std::mutex mutex;
  static std::unordered_set<std::string> pool; // node-based: element addresses are stable
  std::lock_guard<std::mutex> lock(mutex);
  return pool.insert(name).first->c_str();
}

} // namespace tioa

#include "tioa/state.hpp"

namespace tioa {

void throw_out_of_domain(const Slot& slot, std::int64_t value) {
  throw ModelError("value " + std::to_string(value) + " is outside the domain of variable '" +
                   slot.name + "'");
}

void throw_read_of_bottom(const Slot& slot) {
  throw ModelError(std::string("read of variable '") + slot.name + "' while it is ⊥");
}

} // namespace tioa
