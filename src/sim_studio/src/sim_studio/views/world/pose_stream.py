"""The links' poses for pages, at each page's own pace and only what moved.

/gazebo/pose_info brings every link's world pose up to 60 times a second. A page asks for the
next frame when it has drawn the last one; it then gets the newest poses (never an older
frame, however slow the page) of only the links that moved since what it was last sent, so a
still world costs neither the connection nor the page's renderer anything. Pure: no ROS calls.
"""

# A link moved when it moved by a tenth of a millimetre, or turned by about 0.01 degrees: far
# below a pixel at any useful zoom, and above what a body held still by a controller jitters by
# when the simulator runs flat out (at 0.01 mm the Katana world's page drew 3-5 frames a second
# of its arm at rest, each frame costing both cores a burst of CPU on a CPU renderer).
POSITION_DIGITS = 4
ROTATION_DIGITS = 4


class PoseFrames:
    def __init__(self):
        self.seq = 0              # grows with every message
        self.names = []           # "model::link", in the message's order
        self.names_version = 0    # grows when the set or order of links changes
        self.poses = []           # per link (x, y, z, qx, qy, qz, qw), rounded

    def update(self, names, poses):
        """A new pose_info message: its names and geometry_msgs/Pose list."""
        names = list(names)
        if names != self.names:
            self.names = names
            self.names_version += 1
        self.poses = [(round(p.position.x, POSITION_DIGITS), round(p.position.y, POSITION_DIGITS),
                       round(p.position.z, POSITION_DIGITS), round(p.orientation.x, ROTATION_DIGITS),
                       round(p.orientation.y, ROTATION_DIGITS), round(p.orientation.z, ROTATION_DIGITS),
                       round(p.orientation.w, ROTATION_DIGITS)) for p in poses]
        self.seq += 1


class PageFrames:
    """What one page was sent, and whether it is waiting for a frame."""

    def __init__(self):
        self.waiting = True  # a new page (or one reconnected) gets its first frame unasked
        self.seq = 0
        self.names_version = 0
        self.sent = []

    def next_frame(self, frames):
        """The fields of the page's next "poses" message, or None when it has everything:
        {"seq", "poses": [index, x, y, z, qx, qy, qz, qw, index, ...]} with "names" when
        the links changed (all poses then)."""
        if frames.seq == self.seq:
            return None
        self.seq = frames.seq
        message = {"seq": frames.seq}
        if self.names_version != frames.names_version:
            self.names_version = frames.names_version
            self.sent = [None] * len(frames.names)
            message["names"] = frames.names
        flat = []
        for i, pose in enumerate(frames.poses):
            if pose != self.sent[i]:
                self.sent[i] = pose
                flat.append(i)
                flat.extend(pose)
        if not flat and "names" not in message:
            return None
        message["poses"] = flat
        return message
