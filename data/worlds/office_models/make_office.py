#!/usr/bin/env python3
"""Writes data/worlds/office.world: a small open-plan office of 10 m x 8 m (desks, a meeting room,
a break corner, storage by the entrance) for measuring the semantic stack on a world nobody tuned
on. Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model
names are what a world author would type; the class is the name less its _<number>.
Run: python3 data/worlds/office_models/make_office.py > data/worlds/office.world"""

W, D, H = 10.0, 8.0, 2.7   # room width (x), depth (y), wall height
T = 0.1                    # wall thickness

COL = {
    "plaster": "0.9 0.9 0.87", "partition": "0.8 0.83 0.86", "wood": "0.6 0.42 0.25",
    "light_wood": "0.78 0.64 0.45", "metal": "0.55 0.57 0.6", "dark_metal": "0.2 0.2 0.22",
    "black": "0.06 0.06 0.07", "fabric": "0.2 0.3 0.5", "sofa_fabric": "0.55 0.25 0.2",
    "white": "0.97 0.97 0.96", "grey_plastic": "0.75 0.75 0.73", "glass": "0.6 0.75 0.85",
    "leaf": "0.2 0.5 0.22", "pot": "0.6 0.3 0.18", "blue_water": "0.4 0.6 0.9",
    "carpet": "0.42 0.44 0.48", "lamp_shade": "0.95 0.9 0.7", "green_locker": "0.35 0.5 0.4",
}
SCRIPT = {"wood": "Gazebo/Wood", "light_wood": "Gazebo/Wood", "carpet": "Gazebo/Carpet"}


def mat(c):
    rgb = COL[c]
    s = f"<script><name>{SCRIPT[c]}</name></script>" if c in SCRIPT else ""
    return (f"<material>{s}<ambient>{rgb} 1</ambient><diffuse>{rgb} 1</diffuse>"
            f"<specular>0.1 0.1 0.1 1</specular></material>")


def box(name, c, x, y, z, sx, sy, sz):
    return (f"<visual name=\"{c}_{name}\"><pose>{x:g} {y:g} {z:g} 0 0 0</pose><geometry><box><size>"
            f"{sx:g} {sy:g} {sz:g}</size></box></geometry>{mat(c)}</visual>")


def cyl(name, c, x, y, z, r, length):
    return (f"<visual name=\"{c}_{name}\"><pose>{x:g} {y:g} {z:g} 0 0 0</pose><geometry><cylinder>"
            f"<radius>{r:g}</radius><length>{length:g}</length></cylinder></geometry>{mat(c)}</visual>")


def sph(name, c, x, y, z, r):
    return (f"<visual name=\"{c}_{name}\"><pose>{x:g} {y:g} {z:g} 0 0 0</pose><geometry><sphere>"
            f"<radius>{r:g}</radius></sphere></geometry>{mat(c)}</visual>")


def model(name, pose, visuals):
    x, y, z, yaw = pose
    body = "\n".join(visuals)
    return (f"  <model name=\"{name}\">\n    <static>true</static>\n"
            f"    <pose>{x:g} {y:g} {z:g} 0 0 {yaw:g}</pose>\n"
            f"    <link name=\"link\">\n{body}\n    </link>\n  </model>")


def legs(c, hx, hy, h, s=0.04):
    return [box(f"leg{i}", c, sx * hx, sy * hy, h / 2, s, s, h)
            for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


# ---- the things (local frames: x right, y forward = away from the user, z up) ----
def turned(v, rpy):
    """A visual rotated in place (cylinders are upright in SDF; rails, knobs and wheels are not)."""
    return v.replace(" 0 0 0</pose>", f" {rpy}</pose>", 1)


def along_x(v):
    return turned(v, "0 1.5708 0")


def along_y(v):
    return turned(v, "1.5708 0 0")


def castors(hx, hy, r=0.04):
    return [sph(f"castor{i}", "rubber", sx * hx, sy * hy, r, r)
            for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


def desk():
    return [box("top", "light_wood", 0, 0, 0.73, 1.4, 0.7, 0.04)] + legs("dark_metal", 0.66, 0.31, 0.71)


def office_chair():
    v = [box("seat", "fabric", 0, 0, 0.48, 0.48, 0.46, 0.07),
         box("back", "fabric", 0, -0.22, 0.82, 0.46, 0.05, 0.55),
         cyl("column", "dark_metal", 0, 0, 0.27, 0.03, 0.4),
         cyl("base", "dark_metal", 0, 0, 0.05, 0.3, 0.04)]
    return v + [box("arm_l", "black", -0.25, 0, 0.63, 0.04, 0.35, 0.04),
                box("arm_r", "black", 0.25, 0, 0.63, 0.04, 0.35, 0.04)]


def monitor():
    return [box("screen", "black", 0, 0, 0.3, 0.58, 0.04, 0.36),
            box("neck", "dark_metal", 0, 0.04, 0.1, 0.05, 0.04, 0.16),
            box("foot", "dark_metal", 0, 0.04, 0.01, 0.22, 0.16, 0.02)]


def keyboard():
    return [box("body", "black", 0, 0, 0.012, 0.44, 0.14, 0.025)]


def desk_lamp():
    return [cyl("base", "dark_metal", 0, 0, 0.012, 0.08, 0.025),
            cyl("pole", "metal", 0, 0, 0.22, 0.012, 0.4),
            cyl("shade", "lamp_shade", 0, 0, 0.45, 0.1, 0.14)]


def conference_table():
    return [box("top", "wood", 0, 0, 0.74, 2.4, 1.1, 0.05)] + legs("wood", 1.05, 0.42, 0.72, 0.08)


def projector_screen():
    return [box("screen", "white", 0, 0, 0, 0.02, 1.8, 1.2),
            box("case", "grey_plastic", 0, 0, 0.63, 0.08, 1.9, 0.08)]


def whiteboard():
    return [box("frame", "metal", 0, 0, 0, 1.6, 0.03, 1.0),
            box("board", "white", 0, -0.016, 0, 1.52, 0.004, 0.92),
            box("tray", "metal", 0, -0.04, -0.5, 1.4, 0.06, 0.02)]


def sofa():
    return [box("seat", "sofa_fabric", 0, 0, 0.25, 1.9, 0.85, 0.42),
            box("back", "sofa_fabric", 0, -0.33, 0.62, 1.9, 0.2, 0.45),
            box("arm_l", "sofa_fabric", -0.87, 0, 0.55, 0.16, 0.85, 0.22),
            box("arm_r", "sofa_fabric", 0.87, 0, 0.55, 0.16, 0.85, 0.22)]


def coffee_machine():
    return [box("body", "black", 0, 0, 0.8, 0.6, 0.55, 1.6),
            box("panel", "grey_plastic", 0, 0.28, 1.2, 0.4, 0.01, 0.3),
            box("cup_bay", "dark_metal", 0, 0.26, 0.8, 0.25, 0.05, 0.25)]


def water_cooler():
    return [box("body", "white", 0, 0, 0.5, 0.32, 0.32, 1.0),
            cyl("bottle", "blue_water", 0, 0, 1.2, 0.13, 0.4)]


def trash_can():
    return [cyl("body", "dark_metal", 0, 0, 0.3, 0.17, 0.6)]


def filing_cabinet():
    v = [box("body", "metal", 0, 0, 0.66, 0.47, 0.62, 1.32)]
    return v + [box(f"handle{i}", "dark_metal", 0, 0.32, 0.2 + 0.32 * i, 0.12, 0.02, 0.02) for i in range(4)]


def printer():
    return [box("body", "grey_plastic", 0, 0, 0.55, 0.6, 0.55, 1.1),
            box("tray", "white", 0, 0.3, 0.95, 0.3, 0.08, 0.02)]


def locker():
    return [box("body", "green_locker", 0, 0, 0.92, 0.9, 0.45, 1.85)] + \
           [box(f"seam{i}", "dark_metal", -0.15 + 0.3 * i, 0.226, 0.92, 0.01, 0.005, 1.8) for i in range(2)]


def plant():
    return [cyl("pot", "pot", 0, 0, 0.2, 0.18, 0.4), sph("foliage", "leaf", 0, 0, 0.85, 0.38),
            cyl("stem", "wood", 0, 0, 0.55, 0.02, 0.4)]


def wall_clock():
    # discs stood upright (roll 90 degrees): the face looks along -y, away from the wall behind it
    up = lambda v: v.replace(" 0 0 0</pose>", " 1.5708 0 0</pose>", 1)
    return [up(cyl("face", "white", 0, 0, 0, 0.17, 0.03)), up(cyl("rim", "black", 0, 0.016, 0, 0.18, 0.005))]


def door():
    # open door leaf, swung 90 degrees against the wall beside its opening
    return [box("leaf", "wood", 0, 0, 1.02, 0.9, 0.04, 2.04),
            cyl("handle", "metal", 0.38, 0.04, 1.0, 0.015, 0.06)]


def window():
    return [box("frame", "white", 0, 0, 0, 1.3, 0.03, 1.2),
            box("pane", "glass", 0, -0.016, 0, 1.2, 0.004, 1.1)]


def wall_builder(height, thickness=T):
    """Wall segments along x or y, as boxes wall_1, wall_2, ...: returns (visuals, wall); every
    generator of an inline world builds its walls with it."""
    v, n = [], [0]

    def wall(x0, y0, x1, y1, z0=0.0, z1=height, c="plaster"):
        n[0] += 1
        sx = abs(x1 - x0) if x1 != x0 else thickness
        sy = abs(y1 - y0) if y1 != y0 else thickness
        v.append(box(f"wall_{n[0]}", c, (x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2, sx, sy, z1 - z0))
    return v, wall


def floor_slab(name, material, w, d):
    return [box(name, material, w / 2, d / 2, -0.01, w, d, 0.02)]


def ceiling_slab(w, d, h):
    return [box("ceiling", "white", w / 2, d / 2, h + 0.01, w, d, 0.02)]


def walls():
    v, wall = wall_builder(H)
    # outer walls; the entrance (x 1.0..1.9) in the south wall
    wall(0, 0, 1.0, 0); wall(1.9, 0, W, 0); wall(1.0, 0, 1.9, 0, 2.1, H)
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    # meeting room (x 6..10, y 4.5..8): partitions with a doorway at x 7.5..8.4 in y = 4.5
    wall(6, 4.5, 6, D, c="partition")
    wall(6, 4.5, 7.5, 4.5, c="partition"); wall(8.4, 4.5, W, 4.5, c="partition")
    wall(7.5, 4.5, 8.4, 4.5, 2.1, H, c="partition")
    return v


def point_light(name, x, y, z, rgb):
    """A ceiling light without shadows (the other generators light their worlds the same way)."""
    return f"""  <light name="{name}" type="point">
    <pose>{x:g} {y:g} {z:g} 0 0 0</pose>
    <diffuse>{rgb} 1</diffuse>
    <specular>0.1 0.1 0.1 1</specular>
    <attenuation><range>12</range><constant>0.4</constant><linear>0.12</linear><quadratic>0.06</quadratic></attenuation>
    <cast_shadows>false</cast_shadows>
  </light>"""


def shell(walls_visuals, floor_name, floor_material, w, d, h):
    """The three structure models every generated world starts with: walls, floor, ceiling."""
    return [model("walls", (0, 0, 0, 0), walls_visuals),
            model("floor", (0, 0, 0, 0), floor_slab(floor_name, floor_material, w, d)),
            model("ceiling", (0, 0, 0, 0), ceiling_slab(w, d, h))]


def corner_room_walls(w, d, h, entrance, room, doorway, thickness=T):
    """The walls of a shop with its entrance (x entrance[0]..[1]) in the south front and a room
    partitioned off in the north-east corner (x > room[0], y > room[1]), entered through a doorway
    (x doorway[0]..[1]) in its south partition; the grocery and the salon are built so."""
    v, wall = wall_builder(h, thickness)
    (e0, e1), (sx, sy), (d0, d1) = entrance, room, doorway
    # outer walls: the front (south) with the entrance, then north, west, east
    wall(0, 0, e0, 0); wall(e1, 0, w, 0); wall(e0, 0, e1, 0, 2.1, h)
    wall(0, d, w, d); wall(0, 0, 0, d); wall(w, 0, w, d)
    # the corner room's partitions: west (x = sx) closed, south (y = sy) with the doorway
    wall(sx, sy, sx, d, c="partition")
    wall(sx, sy, d0, sy, c="partition"); wall(d1, sy, w, sy, c="partition")
    wall(d0, sy, d1, sy, 2.1, h, c="partition")
    return v


def world_sdf(world, comment, lights, models):
    """The whole SDF document: the comment, scene, a dim sun, the lights and the models."""
    return f"""<?xml version="1.0"?>
<!-- {comment} -->
<sdf version="1.6">
<world name="{world}">
  <scene>
    <ambient>0.4 0.4 0.4 1</ambient>
    <background>0.7 0.8 0.95 1</background>
    <shadows>false</shadows>
  </scene>
  <light name="sun" type="directional">
    <pose>0 0 10 0 0 0</pose>
    <diffuse>0.35 0.35 0.33 1</diffuse>
    <direction>-0.4 0.25 -0.88</direction>
  </light>
{chr(10).join(lights)}
{chr(10).join(models)}
</world>
</sdf>"""


def main():
    out = shell(walls(), "floor_office", "carpet", W, D, H)
    add = lambda name, pose, vis: out.append(model(name, pose, vis))
    # open-plan desks: two rows of two, chairs on the south side, screens facing them
    desks = [(1.6, 3.0), (3.4, 3.0), (1.6, 5.6), (3.4, 5.6)]
    for i, (x, y) in enumerate(desks, 1):
        add(f"desk_{i}", (x, y, 0, 0), desk())
        add(f"office_chair_{i}", (x, y - 0.65, 0, 0), office_chair())
        add(f"monitor_{i}", (x, y + 0.15, 0.75, 3.1416), monitor())
        add(f"keyboard_{i}", (x, y - 0.15, 0.75, 0), keyboard())
        add(f"desk_lamp_{i}", (x + 0.55, y + 0.2, 0.75, 0), desk_lamp())
    add("trash_can_1", (2.5, 2.2, 0, 0), trash_can())
    # meeting room
    add("conference_table", (8.0, 6.35, 0, 0), conference_table())
    for i, (x, y, yaw) in enumerate(((7.4, 5.65, 0), (8.6, 5.65, 0), (7.4, 7.05, 3.1416),
                                     (8.6, 7.05, 3.1416)), 5):
        add(f"office_chair_{i}", (x, y, 0, yaw), office_chair())
    add("projector_screen", (W - T / 2 - 0.02, 6.35, 1.6, 0), projector_screen())
    add("whiteboard", (7.6, D - T / 2 - 0.02, 1.4, 0), whiteboard())
    add("door_2", (8.37, 4.97, 0, 1.5708), door())  # the meeting room's, hinged at x 8.4
    # break corner (south-east)
    add("sofa", (8.3, 0.55, 0, 3.1416), sofa())
    add("window_3", (8.3, T / 2 + 0.02, 1.6, 0), window())  # above the sofa
    add("coffee_machine", (W - 0.4, 2.2, 0, 1.5708), coffee_machine())
    add("water_cooler", (W - 0.3, 3.1, 0, 1.5708), water_cooler())
    add("trash_can_2", (W - 0.3, 3.7, 0, 0), trash_can())
    # storage and the printer on the west wall, lockers by the entrance
    add("filing_cabinet_1", (0.4, 6.9, 0, -1.5708), filing_cabinet())
    add("filing_cabinet_2", (0.4, 7.45, 0, -1.5708), filing_cabinet())
    add("printer", (0.4, 1.7, 0, -1.5708), printer())
    add("trash_can_3", (0.3, 2.4, 0, 0), trash_can())
    add("locker_1", (3.2, 0.3, 0, 0), locker())
    add("locker_2", (4.15, 0.3, 0, 0), locker())
    add("door_1", (1.04, 0.47, 0, 1.5708), door())  # the entrance, hinged at x 1.0
    # plants, windows, the clock
    add("plant_1", (2.35, 0.35, 0, 0), plant())
    add("plant_2", (5.5, 7.55, 0, 0), plant())
    add("window_1", (1.8, D - T / 2 - 0.02, 1.5, 0), window())
    add("window_2", (4.2, D - T / 2 - 0.02, 1.5, 0), window())
    add("wall_clock", (3.0, D - T / 2 - 0.02, 2.2, 0), wall_clock())
    lights = [point_light(name, x, y, 2.45, "0.75 0.74 0.7")
              for name, x, y in (("light_desks_w", 2.5, 3.0), ("light_desks_e", 2.5, 5.6),
                                 ("light_meeting", 8.0, 6.3), ("light_break", 8.0, 2.2))]
    print(world_sdf("semsplat_office", """The semsplat office: an open-plan office of 10 m x 8 m (four desks, a meeting room in the
     north-east, a break corner in the south-east, storage and the printer on the west wall) for
     measuring on a world nobody tuned on. Generated by office_models/make_office.py; all models
     are inline.""", lights, out))


if __name__ == "__main__":
    main()
