// rostest (test/no_delay.test): sendWithoutDelay() on a ROS node's sockets, and on a connection its
// listening socket accepts afterwards (as a subscriber's would be).
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <ros/connection_manager.h>
#include <ros/ros.h>
#include <sys/socket.h>
#include <unistd.h>

#include "publish_thread/no_delay.h"

namespace {

struct TcpSockets {
  int count = 0;
  int with_nagle = 0;  // TCP_NODELAY off
};

// The process's TCP sockets, but for `except`.
TcpSockets tcpSockets(int except = -1) {
  TcpSockets s;
  for (int fd = 0; fd < 1024; ++fd) {
    int type = 0, domain = 0, nodelay = 0;
    socklen_t length = sizeof(int);
    if (fd == except || getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &length) != 0 || type != SOCK_STREAM) continue;
    length = sizeof(int);
    if (getsockopt(fd, SOL_SOCKET, SO_DOMAIN, &domain, &length) != 0 || (domain != AF_INET && domain != AF_INET6))
      continue;
    ++s.count;
    length = sizeof(int);
    if (getsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &nodelay, &length) == 0 && nodelay == 0) ++s.with_nagle;
  }
  return s;
}

TEST(NoDelay, SetsEveryTcpSocketAndWhatTheListeningSocketAcceptsLater) {
  ros::NodeHandle node;  // opens roscpp's listening socket (and its XML-RPC server's)
  const TcpSockets before = tcpSockets();
  ASSERT_GE(before.with_nagle, 1) << "roscpp already sets TCP_NODELAY: nothing to test";
  EXPECT_EQ(publish_thread::sendWithoutDelay(), before.count);
  EXPECT_EQ(tcpSockets().with_nagle, 0);

  // A subscriber connecting now: roscpp accepts the connection on a socket of its own.
  const int client = socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(client, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(ros::ConnectionManager::instance()->getTCPPort()));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(connect(client, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(5.0);
  while (tcpSockets(client).count < before.count + 1 && ros::WallTime::now() < deadline)
    ros::WallDuration(0.01).sleep();
  const TcpSockets after = tcpSockets(client);
  close(client);
  ASSERT_EQ(after.count, before.count + 1) << "roscpp did not accept the connection";
  EXPECT_EQ(after.with_nagle, 0) << "the accepted connection did not inherit TCP_NODELAY";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "no_delay_check");
  return RUN_ALL_TESTS();
}
