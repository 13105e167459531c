#include "publish_thread/no_delay.h"

#include <dirent.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <sys/stat.h>

#include <cstdlib>

namespace publish_thread {
namespace {

bool isTcpSocket(int fd) {
  struct stat s;
  if (fstat(fd, &s) != 0 || !S_ISSOCK(s.st_mode)) return false;
  int domain = 0, type = 0;
  socklen_t length = sizeof(int);
  if (getsockopt(fd, SOL_SOCKET, SO_DOMAIN, &domain, &length) != 0) return false;
  length = sizeof(int);
  if (getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &length) != 0) return false;
  return (domain == AF_INET || domain == AF_INET6) && type == SOCK_STREAM;
}

}  // namespace

int sendWithoutDelay() {
  DIR* fds = opendir("/proc/self/fd");
  if (fds == nullptr) return 0;
  int set = 0;
  const int own = dirfd(fds);
  while (const dirent* entry = readdir(fds)) {
    char* end = nullptr;
    const long fd = std::strtol(entry->d_name, &end, 10);
    if (end == entry->d_name || *end != '\0' || fd == own || !isTcpSocket(static_cast<int>(fd))) continue;
    const int on = 1;
    if (setsockopt(static_cast<int>(fd), IPPROTO_TCP, TCP_NODELAY, &on, sizeof(on)) == 0) ++set;
  }
  closedir(fds);
  return set;
}

}  // namespace publish_thread
