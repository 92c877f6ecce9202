#include "bench/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

namespace hullpack {
namespace {

bool WriteAll(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

double Seconds(const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) * 1e-6; }

}  // namespace

double CurrentRssMb() {
  FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return 0;
  char line[256];
  double kb = 0;
  while (std::fgets(line, sizeof(line), f)) {
    if (std::strncmp(line, "VmRSS:", 6) == 0) {
      kb = std::strtod(line + 6, nullptr);
      break;
    }
  }
  std::fclose(f);
  return kb / 1024.0;
}

ChildResult RunInChild(const std::function<std::vector<uint8_t>()>& work, double timeout_seconds) {
  ChildResult r;
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    r.error = std::string("pipe: ") + std::strerror(errno);
    return r;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) {
    r.error = std::string("fork: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return r;
  }
  if (pid == 0) {
    close(fds[0]);
    const double base = CurrentRssMb();
    std::vector<uint8_t> payload;
    try {
      payload = work();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "child: %s\n", e.what());
      _exit(3);
    } catch (...) {
      _exit(3);
    }
    const uint64_t size = payload.size();
    const bool written = WriteAll(fds[1], &base, sizeof(base)) &&
                         WriteAll(fds[1], &size, sizeof(size)) &&
                         WriteAll(fds[1], payload.data(), payload.size());
    _exit(written ? 0 : 4);
  }
  close(fds[1]);
  std::vector<uint8_t> received;
  bool timed_out = false;
  for (;;) {
    int wait_ms = -1;
    if (timeout_seconds > 0) {
      const double left =
          timeout_seconds -
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (left <= 0) {
        timed_out = true;
        break;
      }
      wait_ms = static_cast<int>(std::min(left * 1000.0, 1e9)) + 1;
    }
    pollfd p = {fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, wait_ms);
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) break;
    if (ready == 0) continue;  // the deadline check above ends the loop
    uint8_t buffer[65536];
    const ssize_t n = read(fds[0], buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file: the child closed its end (it exited)
    received.insert(received.end(), buffer, buffer + n);
  }
  close(fds[0]);
  if (timed_out) kill(pid, SIGKILL);
  int status = 0;
  rusage usage;
  std::memset(&usage, 0, sizeof(usage));
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.peak_rss_mb = double(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
  r.cpu_seconds = Seconds(usage.ru_utime) + Seconds(usage.ru_stime);
  if (timed_out) {
    char text[64];
    std::snprintf(text, sizeof(text), "timed out after %.0f s", timeout_seconds);
    r.error = text;
    return r;
  }
  if (WIFSIGNALED(status)) {
    r.error = "killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
              strsignal(WTERMSIG(status)) + ")";
    return r;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    r.error = "exited with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return r;
  }
  uint64_t size = 0;
  if (received.size() < sizeof(double) + sizeof(size)) {
    r.error = "no result from the child";
    return r;
  }
  std::memcpy(&r.base_rss_mb, received.data(), sizeof(double));
  std::memcpy(&size, received.data() + sizeof(double), sizeof(size));
  if (received.size() != sizeof(double) + sizeof(size) + size) {
    r.error = "short result from the child";
    return r;
  }
  r.payload.assign(received.begin() + sizeof(double) + sizeof(size), received.end());
  r.ok = true;
  return r;
}

void PayloadWriter::Double(double v) { Bytes(&v, sizeof(v)); }
void PayloadWriter::U64(uint64_t v) { Bytes(&v, sizeof(v)); }
void PayloadWriter::Bytes(const void* data, size_t size) {
  const uint8_t* p = static_cast<const uint8_t*>(data);
  bytes_.insert(bytes_.end(), p, p + size);
}

bool PayloadReader::Double(double* v) { return Bytes(v, sizeof(*v)); }
bool PayloadReader::U64(uint64_t* v) { return Bytes(v, sizeof(*v)); }
bool PayloadReader::Bytes(void* data, size_t size) {
  if (!ok_ || bytes_.size() - at_ < size) {
    ok_ = false;
    return false;
  }
  if (size) std::memcpy(data, bytes_.data() + at_, size);
  at_ += size;
  return true;
}

}  // namespace hullpack
