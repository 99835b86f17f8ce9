#include "checker/symbolic_apart.hpp"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace checker::symbolic {

namespace {

// The result as bytes through a pipe: the numbers, then each vector's length and words.
void put(std::string& out, const void* data, std::size_t size) {
  out.append(static_cast<const char*>(data), size);
}
template <class T> void put(std::string& out, const T& value) {
  put(out, &value, sizeof value);
}
void put_words(std::string& out, const std::vector<Word>& words) {
  put(out, static_cast<std::uint64_t>(words.size()));
  put(out, words.data(), words.size() * sizeof(Word));
}

std::string encode(const StabilisationResult& r) {
  std::string out;
  put(out, r.start_states);
  put(out, r.reachable);
  put(out, static_cast<std::uint8_t>(r.worst.has_value()));
  put(out, r.worst.value_or(0));
  put(out, r.layers);
  put(out, r.late_outside);
  put(out, r.time_locked);
  put(out, r.zero_time_forever);
  put(out, static_cast<std::uint8_t>(r.stopped));
  put_words(out, r.worst_start);
  put_words(out, r.time_lock_start);
  return out;
}

class Reader {
public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <class T> T get() {
    T value{};
    if (at_ + sizeof value > bytes_.size())
      throw std::runtime_error("stabilise_apart: the child's result is cut short");
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  std::vector<Word> words() {
    std::vector<Word> w(get<std::uint64_t>());
    for (Word& x : w)
      x = get<Word>();
    return w;
  }

private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

StabilisationResult decode(const std::string& bytes) {
  Reader in(bytes);
  StabilisationResult r;
  r.start_states = in.get<double>();
  r.reachable = in.get<double>();
  const bool has_worst = in.get<std::uint8_t>();
  const auto worst = in.get<std::uint64_t>();
  if (has_worst)
    r.worst = worst;
  r.layers = in.get<std::uint64_t>();
  r.late_outside = in.get<double>();
  r.time_locked = in.get<double>();
  r.zero_time_forever = in.get<double>();
  r.stopped = in.get<std::uint8_t>();
  r.worst_start = in.words();
  r.time_lock_start = in.words();
  return r;
}

void write_all(int fd, const std::string& bytes) {
  for (std::size_t at = 0; at < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + at, bytes.size() - at);
    if (n <= 0)
      return;
    at += static_cast<std::size_t>(n);
  }
}

} // namespace

StabilisationResult stabilise_apart(const System& system, const bdd& start, const bdd& legal,
                                    std::uint64_t witness_after,
                                    const std::function<bool()>& stop) {
  int fds[2];
  if (::pipe(fds) != 0)
    return stabilise(system, start, legal, witness_after);
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return stabilise(system, start, legal, witness_after);
  }
  if (child == 0) {
    ::close(fds[0]);
    int status = 0;
    try {
      write_all(fds[1], encode(stabilise(system, start, legal, witness_after)));
    } catch (...) {
      status = 1; // (the parent sees a result cut short)
    }
    ::close(fds[1]);
    ::_exit(status); // no destructors, no atexit: the parent owns everything
  }
  ::close(fds[1]);
  std::string bytes;
  bool stopped = false;
  for (;;) {
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, 100);
    if (ready > 0) {
      char buffer[1 << 16];
      const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
      if (n > 0) {
        bytes.append(buffer, static_cast<std::size_t>(n));
        continue;
      }
      if (n == 0)
        break; // the child closed its end: done
    }
    if (stop && stop()) {
      ::kill(child, SIGKILL);
      stopped = true;
      break;
    }
  }
  ::close(fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  if (stopped) {
    StabilisationResult r;
    r.start_states = system.space().count(start);
    r.stopped = true;
    return r;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("stabilise_apart: the child process failed");
  return decode(bytes);
}

} // namespace checker::symbolic
