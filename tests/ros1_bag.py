"""Small ROS 1 bags (format 2.0) for the CLI tests: a drive through a rectangular room written
as sensor_msgs/LaserScan, tf2_msgs/TFMessage and nav_msgs/Odometry messages, with whatever the
test needs to break (a tf loop, impossible range limits, readings that are all no-returns).

The layout follows wiki.ros.org/Bags/Format/2.0: the version line, a bag header record padded
to 4096 bytes, connection records, message data records (no chunks), and at index_pos the
connection records again, so that the bag reads as complete. ROS 1 serialization is
little-endian without alignment; strings carry a u32 length and no NUL; std_msgs/Header starts
with a u32 seq.

    import ros1_bag
    bag = ros1_bag.Drive()                   # 10 s at 1 m/s, scans at 10 Hz, tf at 20 Hz
    bag.static_tf("base_link", "laser", x=0.1)
    bag.write("drive.bag")
"""

import math
import struct


def _field(name, value):
    if isinstance(value, str):
        value = value.encode()
    entry = name.encode() + b"=" + value
    return struct.pack("<I", len(entry)) + entry


def _record(fields, data):
    header = b"".join(_field(k, v) for k, v in fields)
    return struct.pack("<I", len(header)) + header + struct.pack("<I", len(data)) + data


def _string(text):
    raw = text.encode()
    return struct.pack("<I", len(raw)) + raw


def _header(seq, stamp_ns, frame):
    return struct.pack("<III", seq, stamp_ns // 10**9, stamp_ns % 10**9) + _string(frame)


def laser_scan(stamp_ns, frame, angle_min, angle_max, angle_increment, range_min, range_max, ranges, seq=0):
    body = _header(seq, stamp_ns, frame)
    body += struct.pack("<7f", angle_min, angle_max, angle_increment, 0.0, 0.1, range_min, range_max)
    body += struct.pack("<I", len(ranges)) + struct.pack("<%df" % len(ranges), *ranges)
    body += struct.pack("<I", 0)  # no intensities
    return body


def yaw_quaternion(yaw):
    return (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))


def tf_message(transforms):
    """transforms: (parent, child, stamp_ns, (x, y, z), (qx, qy, qz, qw)) each."""
    body = struct.pack("<I", len(transforms))
    for parent, child, stamp_ns, t, q in transforms:
        body += _header(0, stamp_ns, parent) + _string(child) + struct.pack("<3d", *t) + struct.pack("<4d", *q)
    return body


def odometry(stamp_ns, frame, child, x, y, yaw, v=0.0, w=0.0):
    body = _header(0, stamp_ns, frame) + _string(child)
    body += struct.pack("<3d", x, y, 0.0) + struct.pack("<4d", *yaw_quaternion(yaw))
    body += struct.pack("<36d", *([0.0] * 36))
    body += struct.pack("<6d", v, 0.0, 0.0, 0.0, 0.0, w) + struct.pack("<36d", *([0.0] * 36))
    return body


TYPES = {
    "sensor_msgs/LaserScan": "90c7ef2dc6895d81024acba2ac42f369",
    "tf2_msgs/TFMessage": "94810edda583a504dfda3829e70d7eec",
    "nav_msgs/Odometry": "cd5e73d190d741a2f92e81eda573aca7",
}


class Bag:
    def __init__(self):
        self.connections = []  # (topic, type, latching)
        self.messages = []     # (conn, time_ns, payload)

    def connection(self, topic, msg_type, latching=False):
        for k, c in enumerate(self.connections):
            if c[0] == topic:
                return k
        self.connections.append((topic, msg_type, latching))
        return len(self.connections) - 1

    def add(self, topic, msg_type, time_ns, payload, latching=False):
        self.messages.append((self.connection(topic, msg_type, latching), time_ns, payload))

    def _connection_records(self):
        out = b""
        for k, (topic, msg_type, latching) in enumerate(self.connections):
            details = [("topic", topic), ("type", msg_type), ("md5sum", TYPES[msg_type]), ("message_definition", "")]
            if latching:
                details.append(("latching", "1"))
            data = b"".join(_field(name, value) for name, value in details)
            out += _record([("op", b"\x07"), ("conn", struct.pack("<I", k)), ("topic", topic)], data)
        return out

    def to_bytes(self):
        body = self._connection_records()
        for conn, time_ns, payload in sorted(self.messages, key=lambda m: m[1]):
            stamp = struct.pack("<II", time_ns // 10**9, time_ns % 10**9)
            body += _record([("op", b"\x02"), ("conn", struct.pack("<I", conn)), ("time", stamp)], payload)
        magic = b"#ROSBAG V2.0\n"
        index_pos = len(magic) + 4096 + len(body)
        fields = [("op", b"\x03"), ("index_pos", struct.pack("<Q", index_pos)),
                  ("conn_count", struct.pack("<I", len(self.connections))), ("chunk_count", struct.pack("<I", 0))]
        header = b"".join(_field(k, v) for k, v in fields)
        padding = 4096 - (4 + len(header) + 4)
        bag_header = struct.pack("<I", len(header)) + header + struct.pack("<I", padding) + b" " * padding
        return magic + bag_header + body + self._connection_records()

    def write(self, path):
        with open(path, "wb") as f:
            f.write(self.to_bytes())


def room_ranges(x, y, yaw, angles, width=12.0, height=8.0):
    """Readings of a laser at (x, y, yaw) inside the box [0, width] x [0, height], with a pillar."""
    out = []
    for a in angles:
        dx, dy = math.cos(yaw + a), math.sin(yaw + a)
        best = float("inf")
        for t in ((-x / dx) if dx < 0 else (width - x) / dx if dx > 0 else float("inf"),
                  (-y / dy) if dy < 0 else (height - y) / dy if dy > 0 else float("inf")):
            best = min(best, t)
        # A 1 m pillar at (6, 6) and a 0.5 m box at (3, 1.5): corners for the matcher.
        for cx, cy, half in ((6.0, 6.0, 0.5), (3.0, 1.5, 0.25)):
            for t in _box_hits(x, y, dx, dy, cx, cy, half):
                best = min(best, t)
        out.append(best)
    return out


def _box_hits(x, y, dx, dy, cx, cy, half):
    hits = []
    for axis, lo, hi in ((0, cx - half, cx + half), (1, cy - half, cy + half)):
        p, d = (x, dx) if axis == 0 else (y, dy)
        if d == 0:
            continue
        for edge in (lo, hi):
            t = (edge - p) / d
            if t <= 0:
                continue
            other = (y + t * dy) if axis == 0 else (x + t * dx)
            olo, ohi = (cy - half, cy + half) if axis == 0 else (cx - half, cx + half)
            if olo <= other <= ohi:
                hits.append(t)
    return hits


class Drive(Bag):
    """A robot driving along y = 4 from x = 1 at 0.5 m/s; base_link in odom on /tf at 20 Hz, the
    laser at the base (base_link -> laser on /tf_static), 181 beams over 180 deg at 10 Hz."""

    def __init__(self, seconds=10.0, speed=0.5, start_s=100.0, range_min=0.05, range_max=30.0, scan_hz=10.0):
        super().__init__()
        self.start_ns = int(start_s * 1e9)
        self.seconds = seconds
        self.speed = speed
        self.static = []
        n = 181
        self.angle_min, self.angle_increment = -math.pi / 2, math.pi / (n - 1)
        self.angle_max = self.angle_min + self.angle_increment * (n - 1)
        angles = [self.angle_min + i * self.angle_increment for i in range(n)]
        for k in range(int(seconds * 20) + 1):
            t = self.start_ns + k * 50_000_000
            x, y, yaw = self.pose(t)
            self.add("/tf", "tf2_msgs/TFMessage", t,
                     tf_message([("odom", "base_link", t, (x, y, 0.0), yaw_quaternion(yaw))]))
        for k in range(int(seconds * scan_hz)):
            t = self.start_ns + 25_000_000 + int(k * 1e9 / scan_hz)
            x, y, yaw = self.pose(t)
            self.scan(t, room_ranges(x, y, yaw, angles), range_min, range_max, seq=k)

    def pose(self, t_ns):
        s = (t_ns - self.start_ns) / 1e9
        return 1.0 + self.speed * s, 4.0, 0.0

    def scan(self, t_ns, ranges, range_min, range_max, seq=0, frame="laser"):
        self.add("/scan", "sensor_msgs/LaserScan", t_ns,
                 laser_scan(t_ns, frame, self.angle_min, self.angle_max, self.angle_increment, range_min, range_max,
                            ranges, seq))

    def static_tf(self, parent, child, x=0.0, y=0.0, yaw=0.0):
        self.static.append((parent, child, self.start_ns, (x, y, 0.0), yaw_quaternion(yaw)))

    def to_bytes(self):
        if self.static:
            self.messages = [m for m in self.messages if self.connections[m[0]][0] != "/tf_static"]
            self.add("/tf_static", "tf2_msgs/TFMessage", self.start_ns, tf_message(self.static), latching=True)
        return super().to_bytes()
