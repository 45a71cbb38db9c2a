#!/usr/bin/env python3
"""Writes data/worlds/apartment.world: a two-bedroom family apartment of 12 m x 9 m for measuring the
semantic stack on a world nobody tuned on. The south half is one open-plan space: the living room
in the south-west (sofa on the south wall under a window, a rug, an armchair, the television on
its cabinet against the north wall, a bookcase, a floor lamp and a houseplant), the dining area in
the middle (a table with four chairs) and the kitchen in the south-east (a run of kitchen counter,
dishwasher, kitchen sink, oven and fridge along its north wall, the toaster and kettle on the
counter, a kitchen island with two bar stools). The north half, from the west: the master bedroom
(double bed with two bedside tables, wardrobe, dresser), the entrance hall (the front door in the
north wall, a shoe rack under coat hooks, a door down into the living room), the bathroom off the
hall (bathtub, toilet, washbasin, washing machine) and, at the end of a short passage, the child's
bedroom (bunk bed, desk, toy chest). Every model is inline (boxes, cylinders, spheres), so the
world needs no model path. Model names are what a world author would type; the class is the name
less its _<number>. Standard library only; the SDF it writes has the same shape as the other
generated worlds (one static model per thing, one link, named visuals).
Run: python3 data/worlds/apartment_models/make_apartment.py > data/worlds/apartment.world"""

import math

W, D, H = 12.0, 9.0, 2.6   # apartment width (x), depth (y), ceiling height
T = 0.1                    # wall thickness
HALF = T / 2
NORTH_Y = 5.0              # the wall between the open-plan south half and the rooms to the north
HALL_X0, HALL_X1 = 4.2, 6.2   # the entrance hall between the master bedroom and the bathroom
KID_X = 8.6                # the child's bedroom: x > KID_X, y > NORTH_Y
PASSAGE_Y = 6.2            # the passage from the hall to the child's room: HALL_X1 < x < KID_X, y < PASSAGE_Y
DOOR_H = 2.05              # doorway height (a lintel above it)
PI = math.pi

COL = {
    "plaster": "0.92 0.91 0.88", "partition": "0.86 0.87 0.84", "tile_wall": "0.82 0.9 0.92",
    "oak_floor": "0.7 0.55 0.38", "white": "0.97 0.97 0.96", "wood": "0.6 0.42 0.25",
    "light_wood": "0.78 0.64 0.45", "dark_wood": "0.35 0.24 0.16", "glass": "0.6 0.75 0.85",
    "metal": "0.55 0.57 0.6", "chrome": "0.8 0.82 0.85", "steel": "0.72 0.73 0.75",
    "black": "0.06 0.06 0.07", "dark_metal": "0.2 0.2 0.22", "screen": "0.1 0.12 0.15",
    "grey_fabric": "0.5 0.5 0.52", "cushion": "0.62 0.62 0.64", "leather_brown": "0.42 0.26 0.16",
    "rug_red": "0.62 0.2 0.18", "rug_cream": "0.9 0.85 0.72", "lamp_shade": "0.95 0.92 0.8",
    "pot": "0.6 0.3 0.18", "leaf": "0.2 0.5 0.22", "book_red": "0.6 0.12 0.12",
    "book_blue": "0.15 0.25 0.55", "book_green": "0.2 0.45 0.25", "book_yellow": "0.85 0.7 0.2",
    "cabinet_white": "0.94 0.94 0.92", "worktop": "0.3 0.3 0.32", "hob": "0.05 0.05 0.05",
    "toaster_red": "0.75 0.1 0.1", "duvet_blue": "0.45 0.6 0.8", "pillow": "0.96 0.96 0.94",
    "mattress": "0.92 0.92 0.88", "duvet_yellow": "0.95 0.8 0.3", "duvet_green": "0.4 0.7 0.45",
    "toy_blue": "0.2 0.4 0.8", "toy_red": "0.85 0.2 0.2", "toy_yellow": "0.95 0.8 0.15",
    "porcelain": "0.97 0.97 0.97", "water": "0.65 0.8 0.9", "rubber": "0.1 0.1 0.1",
    "grey_plastic": "0.75 0.75 0.73", "shoe_black": "0.1 0.09 0.08", "shoe_white": "0.9 0.9 0.88",
    "coat_navy": "0.15 0.18 0.3", "tv_black": "0.08 0.08 0.09",
}


def fmt(v):
    v = round(v, 4)
    if v == 0:
        v = 0.0  # no "-0"
    return format(v, "g")


def vec(*vs):
    return " ".join(fmt(v) for v in vs)


def material(color):
    rgb = COL[color]
    script = "<script><name>Gazebo/Wood</name></script>" if "wood" in color else ""
    return (f"<material>{script}<ambient>{rgb} 1</ambient><diffuse>{rgb} 1</diffuse>"
            f"<specular>0.1 0.1 0.1 1</specular></material>")


def visual(name, color, pose, geometry, label=None):
    return (f'<visual name="{label or color + "_" + name}"><pose>{vec(*pose)}</pose><geometry>{geometry}</geometry>'
            f"{material(color)}</visual>")


def box(name, color, x, y, z, sx, sy, sz, rpy=(0, 0, 0)):
    return visual(name, color, (x, y, z) + tuple(rpy), f"<box><size>{vec(sx, sy, sz)}</size></box>")


def cyl(name, color, x, y, z, r, length, rpy=(0, 0, 0)):
    return visual(name, color, (x, y, z) + tuple(rpy),
                  f"<cylinder><radius>{fmt(r)}</radius><length>{fmt(length)}</length></cylinder>")


def sph(name, color, x, y, z, r):
    return visual(name, color, (x, y, z, 0, 0, 0), f"<sphere><radius>{fmt(r)}</radius></sphere>")


def legs(color, hx, hy, h, t, z0=0.0):
    """Four square legs at (+-hx, +-hy) from z0 up to z0 + h."""
    return [box(f"leg{i}", color, sx * hx, sy * hy, z0 + h / 2, t, t, h)
            for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


def model(name, pose, visuals):
    x, y, z, yaw = pose
    body = "\n".join(visuals)
    return (f'  <model name="{name}">\n    <static>true</static>\n    <pose>{vec(x, y, z, 0, 0, yaw)}</pose>\n'
            f'    <link name="link">\n{body}\n    </link>\n  </model>')


def point_light(name, x, y, z, rgb):
    return (f'  <light name="{name}" type="point">\n    <pose>{vec(x, y, z, 0, 0, 0)}</pose>\n'
            f"    <diffuse>{rgb} 1</diffuse>\n    <specular>0.1 0.1 0.1 1</specular>\n"
            "    <attenuation><range>12</range><constant>0.4</constant><linear>0.12</linear>"
            "<quadratic>0.06</quadratic></attenuation>\n    <cast_shadows>false</cast_shadows>\n  </light>")


# ---- the shell ----
class Walls:
    """Collects wall boxes; a wall with doorways is written as its solid pieces plus lintels."""

    def __init__(self):
        self.v = []

    def add(self, kind, color, x, y, sx, sy, z0=0.0, z1=H):
        """One wall box; its visual is called <kind>_wall_<n> like the other generated worlds."""
        n = len(self.v) + 1
        self.v.append(visual(f"wall_{n}", color, (x, y, (z0 + z1) / 2, 0, 0, 0),
                             f"<box><size>{vec(sx, sy, z1 - z0)}</size></box>", label=f"{kind}_wall_{n}"))

    def along_x(self, kind, color, y, x0, x1, gaps=()):
        """A wall on the line y from x0 to x1, with doorways (a, b) cut out below DOOR_H."""
        cuts = sorted(gaps)
        a = x0
        for g0, g1 in cuts:
            if g0 > a:
                self.add(kind, color, (a + g0) / 2, y, g0 - a, T)
            a = g1
        if x1 > a:
            self.add(kind, color, (a + x1) / 2, y, x1 - a, T)
        for g0, g1 in cuts:
            self.add(kind, color, (g0 + g1) / 2, y, g1 - g0, T, DOOR_H, H)

    def along_y(self, kind, color, x, y0, y1, gaps=()):
        cuts = sorted(gaps)
        a = y0
        for g0, g1 in cuts:
            if g0 > a:
                self.add(kind, color, x, (a + g0) / 2, T, g0 - a)
            a = g1
        if y1 > a:
            self.add(kind, color, x, (a + y1) / 2, T, y1 - a)
        for g0, g1 in cuts:
            self.add(kind, color, x, (g0 + g1) / 2, T, g1 - g0, DOOR_H, H)


FRONT_DOOR = (4.9, 5.8)      # in the north wall, into the hall
HALL_DOOR = (4.8, 5.7)       # in the wall y = NORTH_Y, from the hall down into the living room
MASTER_DOOR = (6.0, 6.9)     # in the hall's west wall x = HALL_X0
BATH_DOOR = (7.0, 7.8)       # in the hall's east wall x = HALL_X1
KID_DOOR = (5.2, 6.0)        # in the child's room's west wall x = KID_X, at the end of the passage


def walls():
    w = Walls()
    w.along_x("plaster", "plaster", 0, 0, W)                               # south outer wall
    w.along_x("plaster", "plaster", D, 0, W, [FRONT_DOOR])                 # north outer wall
    w.along_y("plaster", "plaster", 0, 0, D)                               # west outer wall
    w.along_y("plaster", "plaster", W, 0, D)                               # east outer wall
    w.along_x("partition", "partition", NORTH_Y, 0, W, [HALL_DOOR])        # open plan | rooms
    w.along_y("partition", "partition", HALL_X0, NORTH_Y, D, [MASTER_DOOR])  # master bedroom | hall
    w.along_y("partition", "tile_wall", HALL_X1, PASSAGE_Y, D, [BATH_DOOR])  # hall | bathroom
    w.along_x("partition", "tile_wall", PASSAGE_Y, HALL_X1, KID_X)         # passage | bathroom
    w.along_y("partition", "partition", KID_X, NORTH_Y, D, [KID_DOOR])     # bathroom, passage | kid
    return model("walls", (0, 0, 0, 0), w.v)


def slab(name, color, z):
    """The floor or the ceiling: one thin box over the whole apartment."""
    return model(name, (0, 0, 0, 0), [box(name, color, W / 2, D / 2, z, W, D, 0.02)])


# ---- the things (local frames: x right, y forward = the side a person faces, z up) ----
def door(width=0.9):
    return [box("leaf", "wood", 0, 0, 1.02, width, 0.04, 2.04),
            cyl("handle", "metal", width / 2 - 0.08, 0.04, 1.0, 0.015, 0.06, (PI / 2, 0, 0))]


def window(width=1.2, height=1.1):
    return [box("frame", "white", 0, 0, 0, width + 0.1, 0.03, height + 0.1),
            box("pane", "glass", 0, 0.016, 0, width, 0.004, height),
            box("mullion", "white", 0, 0.02, 0, 0.04, 0.01, height)]


def shoe_rack():
    """A low open rack of two slatted shelves with a few pairs of shoes, 0.9 x 0.3 x 0.5."""
    v = [box("side_l", "light_wood", -0.43, 0, 0.25, 0.04, 0.3, 0.5),
         box("side_r", "light_wood", 0.43, 0, 0.25, 0.04, 0.3, 0.5)]
    for i, z in enumerate((0.06, 0.28, 0.48)):
        v.append(box(f"shelf{i}", "light_wood", 0, 0, z, 0.82, 0.28, 0.02))
    for k, x in enumerate((-0.28, -0.02, 0.24)):
        c = ("shoe_black", "shoe_white")[k % 2]
        v += [box(f"shoe{k}a", c, x - 0.05, 0, 0.12, 0.09, 0.26, 0.09),
              box(f"shoe{k}b", c, x + 0.05, 0, 0.12, 0.09, 0.26, 0.09)]
    return v


def coat_hooks():
    """A wall board of four hooks (the wall behind it at -y), one coat hanging from it."""
    v = [box("board", "dark_wood", 0, 0, 0, 0.8, 0.02, 0.1)]
    v += [box(f"hook{i}", "dark_metal", -0.3 + 0.2 * i, 0.04, 0.0, 0.02, 0.07, 0.02) for i in range(4)]
    return v + [box("coat", "coat_navy", -0.1, 0.09, -0.45, 0.42, 0.12, 0.85)]


def fridge():
    """A tall single-door fridge, 0.75 x 0.7 x 1.85, its door at +y."""
    return [box("body", "steel", 0, 0, 0.925, 0.75, 0.7, 1.85),
            box("handle", "chrome", 0.3, 0.37, 1.1, 0.03, 0.03, 0.7),
            box("seam", "dark_metal", 0, 0.351, 0.925, 0.73, 0.002, 1.8)]


def oven():
    """A freestanding cooker: the oven with its glass door at +y, four rings on the hob on top."""
    v = [box("body", "steel", 0, 0, 0.45, 0.6, 0.6, 0.9),
         box("door", "black", 0, 0.301, 0.42, 0.52, 0.004, 0.5),
         box("window", "glass", 0, 0.304, 0.44, 0.36, 0.002, 0.24),
         box("handle", "chrome", 0, 0.32, 0.72, 0.45, 0.03, 0.02),
         box("hob", "hob", 0, 0, 0.905, 0.58, 0.58, 0.01),
         box("controls", "black", 0, 0.301, 0.8, 0.52, 0.004, 0.08)]
    return v + [cyl(f"ring{i}", "dark_metal", sx * 0.14, sy * 0.14, 0.912, 0.08, 0.005)
                for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


def base_unit(width):
    """A kitchen base cabinet with its worktop (the parts the counter, sink and dishwasher share)."""
    return [box("cabinet", "cabinet_white", 0, -0.02, 0.44, width, 0.56, 0.88),
            box("worktop", "worktop", 0, 0, 0.9, width, 0.6, 0.04)]


def kitchen_counter(width=1.0):
    v = base_unit(width)
    v += [box(f"handle{i}", "chrome", x, 0.265, 0.75, 0.15, 0.02, 0.02)
          for i, x in enumerate((-width / 4, width / 4))]
    return v + [box("door_seam", "grey_plastic", 0, 0.261, 0.4, 0.005, 0.002, 0.7)]


def kitchen_sink():
    """A sink base unit: a steel bowl let into the worktop, a swan-neck tap behind it."""
    return base_unit(0.8) + [
        box("bowl", "steel", 0, 0.02, 0.905, 0.5, 0.4, 0.012),
        box("drain", "dark_metal", 0, 0.02, 0.912, 0.06, 0.06, 0.002),
        cyl("tap", "chrome", 0, -0.22, 1.05, 0.015, 0.3),
        cyl("spout", "chrome", 0, -0.14, 1.2, 0.012, 0.16, (PI / 2, 0, 0)),
        box("door_seam", "grey_plastic", 0, 0.261, 0.4, 0.005, 0.002, 0.7)]


def dishwasher():
    """An integrated dishwasher under the worktop, its steel front at +y."""
    return [box("body", "steel", 0, -0.02, 0.44, 0.6, 0.56, 0.86),
            box("worktop", "worktop", 0, 0, 0.9, 0.6, 0.6, 0.04),
            box("panel", "black", 0, 0.261, 0.82, 0.56, 0.004, 0.06),
            box("handle", "chrome", 0, 0.275, 0.74, 0.4, 0.02, 0.02)]


def kitchen_island(length=1.8, depth=0.9):
    """A freestanding island: a cabinet block under a worktop that overhangs toward the stools (+y)."""
    return [box("cabinet", "cabinet_white", 0, -0.05, 0.44, length, depth - 0.1, 0.88),
            box("worktop", "worktop", 0, 0.05, 0.9, length + 0.1, depth + 0.1, 0.04),
            box("plinth", "dark_metal", 0, -0.05, 0.04, length - 0.05, depth - 0.15, 0.08)]


def bar_stool():
    return [cyl("base", "chrome", 0, 0, 0.015, 0.2, 0.03),
            cyl("pole", "chrome", 0, 0, 0.36, 0.025, 0.66),
            cyl("footring", "chrome", 0, 0, 0.3, 0.16, 0.015),
            cyl("seat", "black", 0, 0, 0.71, 0.19, 0.06),
            box("back", "black", 0, -0.17, 0.88, 0.3, 0.03, 0.22)]


def toaster():
    return [box("body", "toaster_red", 0, 0, 0.1, 0.28, 0.16, 0.2),
            box("slot1", "black", 0, -0.03, 0.201, 0.2, 0.03, 0.002),
            box("slot2", "black", 0, 0.03, 0.201, 0.2, 0.03, 0.002),
            box("lever", "chrome", 0.145, 0, 0.14, 0.01, 0.03, 0.02)]


def kettle():
    return [cyl("base", "black", 0, 0, 0.01, 0.09, 0.02),
            cyl("body", "steel", 0, 0, 0.13, 0.08, 0.22),
            box("handle", "black", -0.1, 0, 0.14, 0.03, 0.03, 0.18),
            cyl("spout", "steel", 0.1, 0, 0.19, 0.015, 0.07, (0, 1.0, 0)),
            cyl("lid", "black", 0, 0, 0.245, 0.06, 0.01)]


def sofa(length=2.0):
    """A three-seater, its back at -y."""
    v = [box("base", "grey_fabric", 0, 0.03, 0.22, length, 0.84, 0.36),
         box("back", "grey_fabric", 0, -0.35, 0.62, length, 0.2, 0.5),
         box("arm_l", "grey_fabric", -length / 2 + 0.08, 0.03, 0.52, 0.16, 0.84, 0.24),
         box("arm_r", "grey_fabric", length / 2 - 0.08, 0.03, 0.52, 0.16, 0.84, 0.24)]
    cw = (length - 0.32) / 3
    return v + [box(f"cushion{i}", "cushion", -length / 2 + 0.16 + cw * (i + 0.5), 0.06, 0.45,
                    cw - 0.02, 0.7, 0.1) for i in range(3)]


def armchair():
    return [box("base", "leather_brown", 0, 0.02, 0.22, 0.85, 0.82, 0.36),
            box("back", "leather_brown", 0, -0.33, 0.65, 0.85, 0.16, 0.55),
            box("arm_l", "leather_brown", -0.36, 0.02, 0.52, 0.13, 0.82, 0.26),
            box("arm_r", "leather_brown", 0.36, 0.02, 0.52, 0.13, 0.82, 0.26),
            box("cushion", "leather_brown", 0, 0.06, 0.44, 0.58, 0.66, 0.08)]


def tv_cabinet(length=1.6):
    """A low media unit, its doors at +y."""
    return [box("body", "black", 0, 0, 0.27, length, 0.45, 0.46),
            box("top", "dark_wood", 0, 0, 0.51, length + 0.02, 0.46, 0.02),
            box("seam", "dark_metal", 0, 0.226, 0.27, 0.005, 0.002, 0.4)] + \
        legs("dark_metal", length / 2 - 0.06, 0.17, 0.04, 0.03)


def television():
    """A flat screen on a pedestal foot (standing on the cabinet), the picture at +y."""
    return [box("foot", "dark_metal", 0, 0, 0.01, 0.35, 0.22, 0.02),
            box("neck", "dark_metal", 0, -0.02, 0.09, 0.06, 0.04, 0.16),
            box("panel", "tv_black", 0, 0, 0.52, 1.24, 0.05, 0.72),
            box("picture", "screen", 0, 0.026, 0.52, 1.18, 0.004, 0.66)]


def bookcase(width=1.0, depth=0.32, height=1.9):
    """A five-shelf bookcase full of books, its open front at +y."""
    v = [box("side_l", "light_wood", -width / 2 + 0.02, 0, height / 2, 0.04, depth, height),
         box("side_r", "light_wood", width / 2 - 0.02, 0, height / 2, 0.04, depth, height),
         box("back", "light_wood", 0, -depth / 2 + 0.01, height / 2, width, 0.02, height),
         box("top", "light_wood", 0, 0, height - 0.01, width, depth, 0.02)]
    books = ("book_red", "book_blue", "book_green", "book_yellow")
    for i in range(5):
        z = 0.04 + 0.37 * i
        v.append(box(f"shelf{i}", "light_wood", 0, 0, z, width - 0.08, depth - 0.02, 0.02))
        v += [box(f"book{i}_{k}", books[(i + k) % 4], -0.36 + 0.09 * k, 0.0, z + 0.14, 0.06, 0.22, 0.26)
              for k in range(8 - (i % 3))]
    return v


def rug(sx=2.4, sy=1.6):
    return [box("field", "rug_red", 0, 0, 0.004, sx, sy, 0.008),
            box("centre", "rug_cream", 0, 0, 0.009, sx - 0.5, sy - 0.5, 0.002)]


def floor_lamp():
    return [cyl("base", "dark_metal", 0, 0, 0.015, 0.15, 0.03),
            cyl("pole", "dark_metal", 0, 0, 0.8, 0.015, 1.55),
            cyl("shade", "lamp_shade", 0, 0, 1.62, 0.2, 0.3),
            sph("bulb", "white", 0, 0, 1.55, 0.04)]


def houseplant():
    return [cyl("pot", "pot", 0, 0, 0.2, 0.18, 0.4),
            cyl("stem", "wood", 0, 0, 0.55, 0.02, 0.4),
            sph("foliage", "leaf", 0, 0, 0.95, 0.35)]


def dining_table(sx=0.9, sy=1.6):
    return [box("top", "light_wood", 0, 0, 0.74, sx, sy, 0.04)] + legs("light_wood", sx / 2 - 0.06, sy / 2 - 0.06,
                                                                     0.72, 0.06)


def dining_chair():
    """A wooden dining chair, the sitter facing +y, its back at -y."""
    return [box("seat", "light_wood", 0, 0, 0.45, 0.44, 0.42, 0.04),
            box("back", "light_wood", 0, -0.2, 0.72, 0.44, 0.03, 0.5)] + legs("light_wood", 0.19, 0.18, 0.43, 0.035)


def double_bed():
    """A 1.6 m double: the headboard at -y against the wall, the foot toward +y."""
    return [box("frame", "dark_wood", 0, 0, 0.17, 1.64, 2.1, 0.26),
            box("headboard", "dark_wood", 0, -1.02, 0.6, 1.64, 0.06, 1.1),
            box("mattress", "mattress", 0, 0.02, 0.4, 1.6, 2.0, 0.2),
            box("duvet", "duvet_blue", 0, 0.3, 0.51, 1.62, 1.4, 0.05),
            box("pillow_l", "pillow", -0.4, -0.8, 0.56, 0.6, 0.35, 0.12),
            box("pillow_r", "pillow", 0.4, -0.8, 0.56, 0.6, 0.35, 0.12)]


def bedside_table():
    return [box("body", "dark_wood", 0, 0, 0.3, 0.45, 0.4, 0.5),
            box("top", "dark_wood", 0, 0, 0.56, 0.47, 0.42, 0.02),
            box("drawer", "light_wood", 0, 0.201, 0.42, 0.38, 0.004, 0.14),
            box("knob", "chrome", 0, 0.21, 0.42, 0.03, 0.02, 0.03)] + legs("dark_wood", 0.19, 0.16, 0.05, 0.03)


def wardrobe(width=1.6, depth=0.6, height=2.1):
    """A two-door wardrobe, the doors at +y."""
    return [box("body", "white", 0, 0, height / 2, width, depth, height),
            box("seam", "grey_plastic", 0, depth / 2 + 0.001, height / 2, 0.006, 0.002, height - 0.1),
            box("handle_l", "chrome", -0.06, depth / 2 + 0.02, 1.1, 0.02, 0.03, 0.3),
            box("handle_r", "chrome", 0.06, depth / 2 + 0.02, 1.1, 0.02, 0.03, 0.3)]


def dresser(width=1.2, depth=0.5, height=0.85):
    """A chest of drawers: three rows of drawers at +y."""
    v = [box("body", "dark_wood", 0, 0, height / 2, width, depth, height)]
    for i in range(3):
        z = 0.17 + 0.26 * i
        v += [box(f"drawer{i}", "light_wood", 0, depth / 2 + 0.002, z, width - 0.08, 0.004, 0.22),
              box(f"knob{i}l", "chrome", -width / 4, depth / 2 + 0.015, z, 0.03, 0.02, 0.03),
              box(f"knob{i}r", "chrome", width / 4, depth / 2 + 0.015, z, 0.03, 0.02, 0.03)]
    return v


def bunk_bed(sx=0.95, sy=2.0):
    """Two stacked single beds on four posts, the long side along y, the ladder on the +x side."""
    v = [box(f"post{i}", "light_wood", a * (sx / 2 - 0.03), b * (sy / 2 - 0.03), 0.85, 0.06, 0.06, 1.7)
         for i, (a, b) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    for lvl, z, duvet in (("lower", 0.25, "duvet_green"), ("upper", 1.2, "duvet_yellow")):
        v += [box(f"{lvl}_frame", "light_wood", 0, 0, z, sx, sy, 0.06),
              box(f"{lvl}_mattress", "mattress", 0, 0, z + 0.1, sx - 0.08, sy - 0.08, 0.14),
              box(f"{lvl}_duvet", duvet, 0, 0.2, z + 0.18, sx - 0.06, sy - 0.5, 0.03),
              box(f"{lvl}_pillow", "pillow", 0, -sy / 2 + 0.25, z + 0.22, 0.5, 0.3, 0.1)]
    v += [box("rail_x", "light_wood", sx / 2 - 0.03, -0.3, 1.5, 0.04, 1.2, 0.06),
          box("rail_back", "light_wood", -sx / 2 + 0.03, 0, 1.5, 0.04, sy - 0.1, 0.06)]
    ladder_y = sy / 2 - 0.35
    v += [box(f"ladder_side{i}", "light_wood", sx / 2 + 0.03, ladder_y + d, 0.7, 0.04, 0.04, 1.4)
          for i, d in enumerate((-0.18, 0.18))]
    v += [box(f"rung{i}", "light_wood", sx / 2 + 0.03, ladder_y, 0.3 + 0.3 * i, 0.03, 0.36, 0.03) for i in range(4)]
    return v


def desk(width=1.2, depth=0.6):
    """A child's desk with a drawer unit on the right, the user at +y."""
    return [box("top", "white", 0, 0, 0.71, width, depth, 0.03),
            box("drawers", "white", width / 2 - 0.2, 0, 0.35, 0.38, depth - 0.04, 0.69),
            box("drawer_front", "toy_blue", width / 2 - 0.2, depth / 2 - 0.018, 0.55, 0.34, 0.004, 0.16),
            box("leg_l0", "white", -width / 2 + 0.03, -depth / 2 + 0.03, 0.35, 0.04, 0.04, 0.69),
            box("leg_l1", "white", -width / 2 + 0.03, depth / 2 - 0.03, 0.35, 0.04, 0.04, 0.69)]


def toy_chest():
    """A lidded wooden box painted in bright colours, 0.9 x 0.5 x 0.5."""
    return [box("body", "toy_blue", 0, 0, 0.22, 0.9, 0.5, 0.44),
            box("lid", "toy_red", 0, 0, 0.465, 0.92, 0.52, 0.05),
            box("band", "toy_yellow", 0, 0.252, 0.22, 0.6, 0.004, 0.1),
            box("handle_l", "dark_metal", -0.46, 0, 0.32, 0.02, 0.12, 0.03),
            box("handle_r", "dark_metal", 0.46, 0, 0.32, 0.02, 0.12, 0.03)]


def toilet():
    """A close-coupled toilet: the cistern at -y against the wall, the bowl toward +y."""
    return [box("cistern", "porcelain", 0, -0.26, 0.62, 0.4, 0.18, 0.4),
            box("flush", "chrome", 0, -0.26, 0.83, 0.06, 0.04, 0.015),
            box("pedestal", "porcelain", 0, 0.02, 0.19, 0.24, 0.34, 0.38),
            cyl("bowl", "porcelain", 0, 0.08, 0.33, 0.19, 0.1),
            cyl("seat", "white", 0, 0.08, 0.4, 0.2, 0.03),
            box("lid_hinge", "white", 0, -0.14, 0.42, 0.3, 0.06, 0.03)]


def bathtub(length=1.6, width=0.75, height=0.55):
    """A built-in bath, the long side along x, the open side at +y, the tap at -x."""
    t = 0.08
    return [box("floor", "porcelain", 0, 0, 0.06, length, width, 0.12),
            box("side_n", "porcelain", 0, -width / 2 + t / 2, height / 2, length, t, height),
            box("side_s", "porcelain", 0, width / 2 - t / 2, height / 2, length, t, height),
            box("end_w", "porcelain", -length / 2 + t / 2, 0, height / 2, t, width, height),
            box("end_e", "porcelain", length / 2 - t / 2, 0, height / 2, t, width, height),
            box("water", "water", 0, 0, 0.3, length - 2 * t, width - 2 * t, 0.01),
            cyl("tap", "chrome", -length / 2 + 0.05, -0.1, height + 0.08, 0.015, 0.16),
            cyl("spout", "chrome", -length / 2 + 0.1, -0.1, height + 0.15, 0.012, 0.12, (0, PI / 2, 0))]


def washbasin():
    """A pedestal washbasin, the tap at -y by the wall, the user at +y."""
    return [box("pedestal", "porcelain", 0, -0.08, 0.4, 0.2, 0.2, 0.8),
            box("basin", "porcelain", 0, 0, 0.84, 0.55, 0.45, 0.14),
            box("bowl", "water", 0, 0.02, 0.912, 0.42, 0.3, 0.002),
            cyl("tap", "chrome", 0, -0.17, 0.97, 0.015, 0.12),
            cyl("spout", "chrome", 0, -0.12, 1.02, 0.012, 0.1, (PI / 2, 0, 0))]


def washing_machine():
    """A front loader, the porthole door at +y."""
    return [box("body", "white", 0, 0, 0.43, 0.6, 0.6, 0.85),
            box("panel", "grey_plastic", 0, 0.28, 0.8, 0.56, 0.05, 0.08),
            cyl("door", "glass", 0, 0.3, 0.42, 0.18, 0.02, (PI / 2, 0, 0)),
            cyl("ring", "chrome", 0, 0.305, 0.42, 0.2, 0.01, (PI / 2, 0, 0))]


# ---- where everything goes ----
def against(wall, along, depth, z=0.0):
    """The pose of a thing of the given depth standing against the inner face of a wall, facing in.
    wall: 's', 'n', 'w' or 'e' side of the room it faces into, with the wall's line coordinate."""
    side, line = wall
    if side == "s":   # the wall is south of the thing, the thing faces north
        return (along, line + HALF + depth / 2, z, 0.0)
    if side == "n":
        return (along, line - HALF - depth / 2, z, PI)
    if side == "w":
        return (line + HALF + depth / 2, along, z, -PI / 2)
    return (line - HALF - depth / 2, along, z, PI / 2)


def doors(add):
    """Each door leaf stands open at right angles to its wall, swung into the room it opens to."""
    # front door: hinged at the east side of its doorway, swung into the hall against nothing
    add("door_1", (FRONT_DOOR[1] - 0.04, D - HALF - 0.45, 0, PI / 2), door(0.9))
    # hall -> living room: hinged at the west jamb, swung up into the hall
    add("door_2", (HALL_DOOR[0] + 0.04, NORTH_Y + HALF + 0.45, 0, PI / 2), door(0.9))
    # hall -> master bedroom: hinged at the north jamb, swung west into the bedroom
    add("door_3", (HALL_X0 - HALF - 0.45, MASTER_DOOR[1] - 0.04, 0, 0), door(0.9))
    # hall -> bathroom: hinged at the north jamb, swung east into the bathroom
    add("door_4", (HALL_X1 + HALF + 0.4, BATH_DOOR[1] - 0.04, 0, 0), door(0.8))
    # passage -> child's bedroom: hinged at the north jamb, swung east into the child's room
    add("door_5", (KID_X + HALF + 0.4, KID_DOOR[1] - 0.04, 0, 0), door(0.8))


def windows(add):
    add("window_1", (2.5, HALF + 0.02, 1.55, 0), window(1.4, 1.2))                    # living room, above the sofa
    add("window_2", (6.7, HALF + 0.02, 1.55, 0), window(1.2, 1.2))                    # dining area
    add("window_3", (W - HALF - 0.02, 2.5, 1.55, PI / 2), window(1.2, 1.1))           # kitchen, east wall
    add("window_4", (1.0, D - HALF - 0.02, 1.5, PI), window(1.0, 1.1))                # master bedroom, north
    add("window_5", (9.6, D - HALF - 0.02, 1.55, PI), window(1.0, 1.0))               # child's room, above the desk
    add("window_6", (7.5, D - HALF - 0.02, 1.85, PI), window(0.6, 0.5))               # bathroom, high up


def hall(add):
    add("shoe_rack", (HALL_X0 + HALF + 0.15, 7.9, 0, -PI / 2), shoe_rack())
    add("coat_hooks", (HALL_X0 + HALF + 0.01, 7.9, 1.7, -PI / 2), coat_hooks())


def living_room(add):
    add("sofa", against(("s", 0), 2.5, 0.9), sofa(2.0))
    add("rug", (2.5, 2.4, 0, 0), rug(2.4, 1.6))
    add("armchair", (0.8, 2.4, 0, -PI / 2), armchair())
    add("tv_cabinet", against(("n", NORTH_Y), 2.5, 0.47), tv_cabinet(1.6))
    x, y, _, yaw = against(("n", NORTH_Y), 2.5, 0.47)
    add("television", (x, y, 0.52, yaw), television())
    add("bookcase", against(("w", 0), 3.95, 0.32), bookcase())
    add("floor_lamp", (3.85, 0.4, 0, 0), floor_lamp())
    add("houseplant", (0.45, 0.45, 0, 0), houseplant())


def dining_area(add):
    add("dining_table", (6.7, 2.5, 0, 0), dining_table(0.9, 1.6))
    k = 1
    for y in (2.1, 2.9):
        add(f"dining_chair_{k}", (5.9, y, 0, -PI / 2), dining_chair())      # west side, facing east
        add(f"dining_chair_{k + 1}", (7.5, y, 0, PI / 2), dining_chair())   # east side, facing west
        k += 2


def kitchen(add):
    n = ("n", NORTH_Y)
    add("kitchen_counter", against(n, 8.6, 0.6), kitchen_counter(1.0))
    add("dishwasher", against(n, 9.4, 0.6), dishwasher())
    add("kitchen_sink", against(n, 10.1, 0.6), kitchen_sink())
    add("oven", against(n, 10.8, 0.6), oven())
    add("fridge", against(n, 11.525, 0.7), fridge())
    x, y, _, yaw = against(n, 8.35, 0.6)
    add("toaster", (x, y - 0.02, 0.92, yaw), toaster())
    x, y, _, yaw = against(n, 8.85, 0.6)
    add("kettle", (x, y, 0.92, yaw), kettle())
    add("kitchen_island", (9.8, 2.45, 0, PI), kitchen_island(1.8, 0.9))   # the overhang faces the stools (south)
    add("bar_stool_1", (9.3, 1.6, 0, 0), bar_stool())
    add("bar_stool_2", (10.3, 1.6, 0, 0), bar_stool())


def master_bedroom(add):
    add("double_bed", against(("w", 0), 7.0, 2.1), double_bed())
    add("bedside_table_1", against(("w", 0), 5.8, 0.43), bedside_table())
    add("bedside_table_2", against(("w", 0), 8.2, 0.43), bedside_table())
    add("wardrobe", against(("n", D), 2.75, 0.6), wardrobe())
    add("dresser", against(("s", NORTH_Y), 2.0, 0.5), dresser())


def child_bedroom(add):
    x, y, z, _ = against(("e", W), 7.8, 0.95 + 0.1)   # the ladder side (+x local) faces the room
    add("bunk_bed", (x, y, z, PI), bunk_bed())
    add("desk", against(("n", D), 9.6, 0.6), desk())
    add("toy_chest", against(("s", NORTH_Y), 10.6, 0.53), toy_chest())


def bathroom(add):
    add("bathtub", (7.75, D - HALF - 0.375, 0, 0), bathtub())
    add("toilet", against(("e", KID_X), 6.9, 0.7), toilet())
    add("washbasin", against(("s", PASSAGE_Y), 7.22, 0.45), washbasin())
    add("washing_machine", against(("s", PASSAGE_Y), 6.57, 0.6), washing_machine())


def main():
    out = [walls(), slab("floor", "oak_floor", -0.01), slab("ceiling", "white", H + 0.01)]
    add = lambda name, pose, vis: out.append(model(name, pose, vis))
    doors(add)
    windows(add)
    hall(add)
    living_room(add)
    dining_area(add)
    kitchen(add)
    master_bedroom(add)
    child_bedroom(add)
    bathroom(add)
    lights = [point_light(name, x, y, H - 0.25, "0.8 0.79 0.76")
              for name, x, y in (("light_living", 2.5, 2.5), ("light_dining", 6.7, 2.5),
                                 ("light_kitchen", 10.0, 3.0), ("light_hall", 5.2, 7.0),
                                 ("light_master", 2.1, 7.0), ("light_bathroom", 7.4, 7.6),
                                 ("light_child", 10.3, 7.0))]
    print('<?xml version="1.0"?>')
    print("""<!-- The semsplat apartment: a two-bedroom family flat of 12 m x 9 m (an open-plan living room,
     dining area and kitchen in the south half; the master bedroom, the entrance hall, the
     bathroom and the child's bedroom in the north half) for measuring on a world nobody tuned on.
     Generated by apartment_models/make_apartment.py; all models are inline. -->""")
    print('<sdf version="1.6">\n<world name="semsplat_apartment">')
    print("  <scene>\n    <ambient>0.4 0.4 0.4 1</ambient>\n    <background>0.7 0.8 0.95 1</background>\n"
          "    <shadows>false</shadows>\n  </scene>")
    print('  <light name="sun" type="directional">\n    <pose>0 0 10 0 0 0</pose>\n'
          "    <diffuse>0.35 0.35 0.33 1</diffuse>\n    <direction>-0.4 0.25 -0.88</direction>\n  </light>")
    print("\n".join(lights))
    print("\n".join(out))
    print("</world>\n</sdf>")


if __name__ == "__main__":
    main()
