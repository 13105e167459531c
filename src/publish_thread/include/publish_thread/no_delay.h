#pragma once
// Sending this process's messages without Nagle's delay.
//
// roscpp sets TCP_NODELAY on a publisher's connection only when the subscriber asks for it
// (ros::TransportHints().tcpNoDelay()), and few subscribers do. Without it the kernel holds a
// message back while the previous one is unacknowledged, and the receiver delays its
// acknowledgement by up to 40 ms: a topic published more often than that arrives in bursts. That is
// harmless at real time, but at 25x real time a 5.5 Hz laser is 137 scans a wall second, and
// hector_mapping got them in bursts 40 ms apart: a second of sim time without a pose.

namespace publish_thread {

// Sets TCP_NODELAY on every TCP socket the process has open, among them roscpp's listening
// socket: on Linux each connection it accepts later (a subscriber of any of the process's topics,
// a client of its services) inherits the setting. Call once after the first ros::NodeHandle (which
// opens that socket). Returns how many sockets were set.
int sendWithoutDelay();

}  // namespace publish_thread
