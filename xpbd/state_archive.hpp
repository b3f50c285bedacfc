// The bytes of a simulation's state, for checkpoints: what a solver carries from one step to
// the next, written by one function shared by saving and loading (the pattern of
// boost::serialization and cereal, whose archives we do not need whole):
//
//   template <class Self, class Archive> static void transfer(Self& self, Archive& archive) {
//     archive(self.x_, self.states_);
//   }
//
// with Self const and a StateWriter to save, non-const and a StateReader to load, so the two
// cannot drift apart. Plain data (numbers, enums, fixed-size Eigen types, structs of those) is
// copied as its bytes; vectors, maps, optionals and strings are written element by element after
// their size. The bytes are this machine's: a checkpoint is read back by the same build.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace rice::xpbd {

/// Copied as its bytes: no pointer, nothing a destructor would free (vectors, strings, maps and
/// shared pointers are not trivially destructible, so they are refused here at compile time).
template <class T>
concept PlainData = std::is_trivially_destructible_v<T> && !std::is_pointer_v<T> && !std::is_empty_v<T>;

/// Appends state to a byte string.
class StateWriter {
 public:
  template <class... T>
  void operator()(const T&... values) {
    (write(values), ...);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  /// Appends `n` bytes from `from`, which may be null when `n` is 0 (an empty vector's data()).
  void put(const void* from, std::size_t n) {
    if (n > 0) bytes_.append(static_cast<const char*>(from), n);
  }
  template <PlainData T>
  void write(const T& value) {
    put(&value, sizeof(T));
  }
  template <class T, int R, int C, int O, int MR, int MC>
    requires(R == Eigen::Dynamic || C == Eigen::Dynamic)
  void write(const Eigen::Matrix<T, R, C, O, MR, MC>& m) {
    write(static_cast<std::int64_t>(m.rows()));
    write(static_cast<std::int64_t>(m.cols()));
    put(m.data(), sizeof(T) * m.size());
  }
  void write(const std::string& s) {
    write(static_cast<std::uint64_t>(s.size()));
    bytes_.append(s);
  }
  template <class T>
  void write(const std::vector<T>& v) {
    write(static_cast<std::uint64_t>(v.size()));
    if constexpr (PlainData<T>) {
      put(v.data(), sizeof(T) * v.size());
    } else {
      for (const T& e : v) write(e);
    }
  }
  template <class K, class V>
  void write(const std::map<K, V>& m) {
    write(static_cast<std::uint64_t>(m.size()));
    for (const auto& [key, value] : m) {
      write(key);
      write(value);
    }
  }
  template <class T>
    requires(!PlainData<std::optional<T>>)
  void write(const std::optional<T>& o) {
    write(o.has_value());
    if (o) write(*o);
  }

  std::string bytes_;
};

/// Reads state back from bytes written by StateWriter; throws std::runtime_error when they end
/// early or a size is larger than the bytes left.
class StateReader {
 public:
  explicit StateReader(std::string_view bytes) : bytes_(bytes) {}
  template <class... T>
  void operator()(T&... values) {
    (read(values), ...);
  }
  /// Whether every byte was read.
  bool at_end() const { return position_ == bytes_.size(); }

 private:
  const char* take(std::size_t n) {
    if (n > bytes_.size() - position_) throw std::runtime_error("the state ends early");
    const char* at = bytes_.data() + position_;
    position_ += n;
    return at;
  }
  /// Copies the next `n` bytes to `to`, which may be null when `n` is 0 (an empty vector's data()).
  void take_into(void* to, std::size_t n) {
    const char* from = take(n);
    if (n > 0) std::memcpy(to, from, n);
  }
  /// A count of elements of `element_size` bytes each, refused when the bytes left cannot hold it.
  std::size_t count(std::size_t element_size) {
    std::uint64_t n = 0;
    read(n);
    if (element_size > 0 && n > (bytes_.size() - position_) / element_size)
      throw std::runtime_error("the state holds a size larger than its bytes");
    return static_cast<std::size_t>(n);
  }
  template <PlainData T>
  void read(T& value) {
    take_into(&value, sizeof(T));
  }
  template <class T, int R, int C, int O, int MR, int MC>
    requires(R == Eigen::Dynamic || C == Eigen::Dynamic)
  void read(Eigen::Matrix<T, R, C, O, MR, MC>& m) {
    std::int64_t rows = 0, cols = 0;
    read(rows);
    read(cols);
    if (rows < 0 || cols < 0 || (R != Eigen::Dynamic && rows != R) || (C != Eigen::Dynamic && cols != C) ||
        (rows > 0 && static_cast<std::uint64_t>(cols) > (bytes_.size() - position_) / sizeof(T) / rows))
      throw std::runtime_error("the state holds a matrix size that does not fit");
    m.resize(rows, cols);
    take_into(m.data(), sizeof(T) * m.size());
  }
  void read(std::string& s) {
    const std::size_t n = count(1);
    s.assign(take(n), n);
  }
  template <class T>
  void read(std::vector<T>& v) {
    if constexpr (PlainData<T>) {
      v.resize(count(sizeof(T)));
      take_into(v.data(), sizeof(T) * v.size());
    } else {
      v.resize(count(1));
      for (T& e : v) read(e);
    }
  }
  template <class K, class V>
  void read(std::map<K, V>& m) {
    m.clear();
    for (std::size_t i = 0, n = count(1); i < n; ++i) {
      std::pair<K, V> entry;
      read(entry.first);
      read(entry.second);
      m.insert(m.end(), std::move(entry));
    }
  }
  template <class T>
    requires(!PlainData<std::optional<T>>)
  void read(std::optional<T>& o) {
    bool has = false;
    read(has);
    if (!has) return o.reset();
    o.emplace();
    read(*o);
  }

  std::string_view bytes_;
  std::size_t position_ = 0;
};

}  // namespace rice::xpbd
