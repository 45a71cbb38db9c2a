// Serializes test messages with an independent ROS 2 CDR writer (@foxglove/rosmsg2-serialization
// over @foxglove/rosmsg-msgs-common's Humble/Jazzy definitions) for tests/ros/test_wire.c.
// usage: node foxglove_write.js cases.json  -> one hex line per case, in order.
// A case is {distro: "humble"|"jazzy", type: "nav_msgs/Odometry"} or {distro, definition: <.msg
// text with MSG: sections>}, plus message; strings "bigint:N" become BigInt (64-bit fields) and
// "num:X" numbers (doubles written with 17 digits, exact).
"use strict";
const fs = require("fs");
const { MessageWriter } = require("@foxglove/rosmsg2-serialization");
const common = require("@foxglove/rosmsg-msgs-common");
const { parse } = require("@foxglove/rosmsg");

function revive(v) {
  if (typeof v === "string" && v.startsWith("bigint:")) return BigInt(v.slice(7));
  if (typeof v === "string" && v.startsWith("num:")) return Number(v.slice(4));
  if (Array.isArray(v)) return v.map(revive);
  if (v && typeof v === "object") {
    const o = {};
    for (const k of Object.keys(v)) o[k] = revive(v[k]);
    return o;
  }
  return v;
}

const cases = JSON.parse(fs.readFileSync(process.argv[2], "utf8"));
for (const c of cases) {
  const lib = common["ros2" + c.distro];
  if (!lib) throw new Error("no definitions for distro " + c.distro);
  const root = c.type ? [lib[c.type]] : parse(c.definition, { ros2: true, skipTypeFixup: true });
  if (!root[0]) throw new Error("no definition for " + c.type);
  const writer = new MessageWriter([...root, ...Object.values(lib)]);
  process.stdout.write(Buffer.from(writer.writeMessage(revive(c.message))).toString("hex") + "\n");
}
