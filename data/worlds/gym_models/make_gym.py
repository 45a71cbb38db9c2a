#!/usr/bin/env python3
"""Writes data/worlds/gym.world: a fitness centre of 20 m x 14 m for measuring the semantic stack on
a world nobody tuned on. The entrance is in the south wall of the lobby in the south-west, with the
reception desk, a sofa and the turnstiles in the lobby's north partition; north of the lobby the
stretching corner (exercise mats, foam rollers, exercise balls, a wall mirror) and, north of that,
two changing rooms side by side (lockers, a bench, three showers, a sink with a mirror each). The
east of the floor is one open hall: the cardio area along the south windows (a row of treadmills
facing the windows with televisions above them, exercise bikes behind, elliptical trainers and
rowing machines), the free-weights area in the north (dumbbell racks with their dumbbells in front
of a long mirror, weight benches, kettlebells, two squat racks with barbells on the east wall, weight
plate racks, a barbell on the floor, a cable machine and a leg press). Water fountains, towel bins,
trash cans, fire extinguishers, a defibrillator, wall clocks and plants as a real gym has them.
Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number>. The primitives and
the SDF writing are the office generator's.
Run: python3 data/worlds/gym_models/make_gym.py > data/worlds/gym.world"""

import math
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, plant)

W, D, H = 20.0, 14.0, 3.2  # floor width (x), depth (y), wall height
T = 0.1                    # wall thickness
XW = 7.0                   # the west block (lobby, stretching corner, changing rooms): x < XW
LY = 4.5                   # the lobby's north partition (the turnstiles), x 0..XW
CY = 8.5                   # the changing rooms' south wall, x 0..XW
XC = 3.5                   # the partition between the two changing rooms
EX0, EX1 = 1.2, 3.0        # the main entrance (two leaves) in the south wall of the lobby
GATE0, GATE1 = 2.8, 5.6    # the opening in the lobby's north partition with the turnstiles
MEN_DOOR = (2.4, 3.3)      # the changing rooms' doorways in y = CY
WOMEN_DOOR = (3.7, 4.6)
PI, HALF = 3.1416, 1.5708

base.COL.update({
    "gym_floor": "0.36 0.37 0.4", "desk_front": "0.15 0.45 0.6", "counter_white": "0.94 0.93 0.9",
    "steel": "0.78 0.8 0.82", "rubber": "0.1 0.1 0.1", "frame_grey": "0.5 0.52 0.55",
    "machine_red": "0.7 0.12 0.1", "screen": "0.1 0.12 0.15", "pad_black": "0.12 0.12 0.13",
    "iron": "0.18 0.18 0.2", "chrome": "0.85 0.86 0.88", "mat_blue": "0.2 0.4 0.75",
    "mat_purple": "0.45 0.25 0.6", "roller_black": "0.15 0.15 0.15", "roller_orange": "0.9 0.5 0.1",
    "ball_green": "0.3 0.7 0.35", "ball_grey": "0.65 0.66 0.68", "locker_grey": "0.55 0.6 0.65",
    "slat_wood": "0.75 0.58 0.38", "tile_white": "0.93 0.94 0.95", "tile_blue": "0.55 0.7 0.8",
    "curtain": "0.85 0.85 0.8", "ceramic": "0.96 0.96 0.97", "mirror_glass": "0.78 0.84 0.88",
    "towel_white": "0.97 0.97 0.95", "bin_blue": "0.2 0.35 0.65", "extinguisher_red": "0.8 0.08 0.06",
    "aed_green": "0.1 0.6 0.3", "kb_pink": "0.9 0.45 0.6", "kb_blue": "0.2 0.35 0.8",
    "kb_yellow": "0.9 0.8 0.15", "kb_purple": "0.5 0.25 0.6", "kb_green": "0.2 0.6 0.25",
    "kb_red": "0.8 0.12 0.1", "plate_black": "0.08 0.08 0.09", "sofa_grey": "0.4 0.42 0.45",
    "reader": "0.1 0.1 0.12", "stack_black": "0.1 0.1 0.1",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned, along_x, along_y = base.turned, base.along_x, base.along_y


def at(x0, y0, yaw, lx, ly):
    """The world point of (lx, ly) in a frame at (x0, y0) turned by yaw."""
    c, s = math.cos(yaw), math.sin(yaw)
    return x0 + lx * c - ly * s, y0 + lx * s + ly * c


# ---- the things (local frames: x right, y forward = the side a person faces, z up) ----
def reception_desk(length=2.4, depth=0.7):
    """The front desk: a tall counter on the members' side (+y) and the work top behind it."""
    return [box("front", "desk_front", 0, depth / 2 - 0.03, 0.55, length, 0.06, 1.1),
            box("top", "counter_white", 0, depth / 2 - 0.1, 1.12, length + 0.05, 0.22, 0.04),
            box("work_top", "counter_white", 0, -0.05, 0.74, length, depth - 0.1, 0.04),
            box("side_l", "desk_front", -length / 2, 0, 0.55, 0.04, depth, 1.1),
            box("side_r", "desk_front", length / 2, 0, 0.55, 0.04, depth, 1.1),
            box("screen", "black", 0.4, -0.1, 1.0, 0.5, 0.04, 0.32),
            box("keyboard", "black", 0.4, -0.3, 0.77, 0.42, 0.14, 0.02)]


def turnstile():
    """A waist-high tripod turnstile: the cabinet along y (people pass along y beside it, on its
    +x side), the card reader on top at the entry end (-y), three arms on a hub to the +x side."""
    return [box("cabinet", "steel", 0, 0, 0.5, 0.3, 1.1, 1.0),
            box("top", "black", 0, 0, 1.01, 0.32, 1.12, 0.02),
            box("reader", "reader", 0, -0.42, 1.04, 0.14, 0.14, 0.04),
            box("light", "aed_green", 0, -0.42, 1.065, 0.06, 0.06, 0.01),
            cyl("hub", "chrome", 0.17, 0, 0.88, 0.06, 0.1),
            box("arm_0", "chrome", 0.4, 0, 0.93, 0.45, 0.035, 0.035),
            turned(box("arm_1", "chrome", 0.33, -0.1, 0.74, 0.35, 0.035, 0.035), "0 0.9 -0.5"),
            turned(box("arm_2", "chrome", 0.33, 0.1, 0.74, 0.35, 0.035, 0.035), "0 0.9 0.5")]


def treadmill():
    """A treadmill: the deck with its belt, the motor hood and the console at the front (+y)."""
    return [box("deck", "black", 0, 0, 0.12, 0.8, 1.9, 0.24),
            box("belt", "rubber", 0, -0.08, 0.245, 0.55, 1.65, 0.01),
            box("hood", "frame_grey", 0, 0.82, 0.22, 0.8, 0.3, 0.22),
            box("upright_l", "frame_grey", -0.37, 0.85, 0.75, 0.06, 0.08, 1.1),
            box("upright_r", "frame_grey", 0.37, 0.85, 0.75, 0.06, 0.08, 1.1),
            box("rail_l", "frame_grey", -0.37, 0.55, 1.05, 0.04, 0.6, 0.04),
            box("rail_r", "frame_grey", 0.37, 0.55, 1.05, 0.04, 0.6, 0.04),
            box("console", "black", 0, 0.85, 1.32, 0.8, 0.22, 0.14),
            box("display", "screen", 0, 0.73, 1.36, 0.4, 0.004, 0.1)]


def exercise_bike():
    """An upright exercise bike: the feet, the frame with its flywheel at the front (+y), the saddle
    behind, the handlebars and the console."""
    return [box("foot_front", "frame_grey", 0, 0.45, 0.03, 0.55, 0.08, 0.06),
            box("foot_back", "frame_grey", 0, -0.45, 0.03, 0.55, 0.08, 0.06),
            box("frame", "machine_red", 0, 0, 0.3, 0.1, 0.9, 0.1),
            along_x(cyl("flywheel", "iron", 0, 0.3, 0.38, 0.24, 0.06)),
            box("cover", "machine_red", 0, 0.3, 0.38, 0.1, 0.5, 0.45),
            box("crank", "iron", 0, 0, 0.35, 0.34, 0.04, 0.03),
            box("seat_post", "frame_grey", 0, -0.28, 0.62, 0.05, 0.05, 0.55),
            box("saddle", "pad_black", 0, -0.28, 0.92, 0.2, 0.28, 0.07),
            box("bar_post", "frame_grey", 0, 0.35, 0.8, 0.05, 0.05, 0.7),
            box("handlebar", "pad_black", 0, 0.42, 1.15, 0.5, 0.05, 0.04),
            box("console", "black", 0, 0.45, 1.24, 0.22, 0.05, 0.15)]


def rowing_machine():
    """An air rower: the rail with the sliding seat, the foot stretchers, the fan housing at the
    front (+y), the handle and the monitor on its arm; the rower sits facing +y."""
    return [box("rail", "chrome", 0, -0.25, 0.3, 0.12, 1.9, 0.05),
            box("leg_back", "iron", 0, -1.15, 0.14, 0.45, 0.08, 0.28),
            box("leg_front", "iron", 0, 0.85, 0.05, 0.55, 0.1, 0.1),
            box("body", "iron", 0, 0.7, 0.35, 0.12, 0.5, 0.2),
            along_x(cyl("fan", "black", 0, 0.95, 0.45, 0.3, 0.25)),
            box("seat", "pad_black", 0, -0.35, 0.37, 0.3, 0.3, 0.07),
            box("footrest_l", "black", -0.1, 0.45, 0.32, 0.14, 0.12, 0.18),
            box("footrest_r", "black", 0.1, 0.45, 0.32, 0.14, 0.12, 0.18),
            box("handle", "black", 0, 0.65, 0.5, 0.5, 0.03, 0.03),
            box("arm", "iron", 0, 0.68, 0.75, 0.04, 0.04, 0.6),
            box("monitor", "black", 0, 0.6, 1.08, 0.2, 0.04, 0.16)]


def elliptical_trainer():
    """An elliptical trainer: the long base, the two foot pedals on their arms, the flywheel housing
    at the front (+y), the moving handles and the console."""
    return [box("base", "iron", 0, 0, 0.06, 0.6, 1.8, 0.12),
            box("housing", "frame_grey", 0, 0.7, 0.4, 0.35, 0.4, 0.6),
            box("pedal_l", "black", -0.15, -0.25, 0.38, 0.15, 0.4, 0.04),
            box("pedal_r", "black", 0.15, -0.05, 0.3, 0.15, 0.4, 0.04),
            box("pedal_arm_l", "frame_grey", -0.15, 0.25, 0.35, 0.05, 0.7, 0.04),
            box("pedal_arm_r", "frame_grey", 0.15, 0.3, 0.3, 0.05, 0.7, 0.04),
            box("upright", "frame_grey", 0, 0.65, 0.95, 0.08, 0.08, 0.9),
            turned(box("handle_l", "chrome", -0.3, 0.5, 1.1, 0.04, 0.04, 1.3), "0.15 0 0"),
            turned(box("handle_r", "chrome", 0.3, 0.5, 1.1, 0.04, 0.04, 1.3), "-0.1 0 0"),
            box("console", "black", 0, 0.66, 1.42, 0.34, 0.1, 0.2)]


def television():
    """A flat screen on a wall bracket, the picture looking along +y."""
    return [box("panel", "black", 0, 0, 0, 1.3, 0.05, 0.75),
            box("picture", "screen", 0, 0.026, 0, 1.24, 0.004, 0.69),
            box("bracket", "iron", 0, -0.05, 0, 0.2, 0.06, 0.2)]


def dumbbell(r):
    """One hex dumbbell lying along x on whatever it stands on: two heads of radius r, the handle."""
    return [along_x(cyl("head_l", "iron", -0.11 - 0.02 * r / 0.07, 0, r, r, 0.07 + 0.6 * (r - 0.05))),
            along_x(cyl("head_r", "iron", 0.11 + 0.02 * r / 0.07, 0, r, r, 0.07 + 0.6 * (r - 0.05))),
            along_x(cyl("handle", "chrome", 0, 0, r, 0.017, 0.2))]


def dumbbell_rack(length=2.4):
    """A two-tier dumbbell rack: the lower tier at the front (+y), the upper one behind it, on two
    end frames; the dumbbells are models of their own lying across the tiers."""
    return [box("tier_low", "iron", 0, 0.12, 0.35, length, 0.26, 0.04),
            box("tier_high", "iron", 0, -0.14, 0.75, length, 0.26, 0.04),
            box("end_l", "frame_grey", -length / 2, 0, 0.38, 0.08, 0.6, 0.76),
            box("end_r", "frame_grey", length / 2, 0, 0.38, 0.08, 0.6, 0.76),
            box("foot_l", "frame_grey", -length / 2, 0, 0.02, 0.12, 0.7, 0.04),
            box("foot_r", "frame_grey", length / 2, 0, 0.02, 0.12, 0.7, 0.04),
            box("label", "white", 0, 0.26, 0.31, length - 0.2, 0.004, 0.05)]


DUMBBELL_TIERS = ((0.12, 0.37), (-0.14, 0.77))  # (y, top of the tier) of the rack's two tiers


def weight_bench():
    """A flat weight bench along y: the padded top on two posts and their feet."""
    return [box("pad", "pad_black", 0, 0, 0.43, 0.3, 1.2, 0.08),
            box("frame", "iron", 0, 0, 0.36, 0.1, 1.05, 0.06),
            box("post_f", "iron", 0, 0.45, 0.19, 0.07, 0.07, 0.34),
            box("post_b", "iron", 0, -0.45, 0.19, 0.07, 0.07, 0.34),
            box("foot_f", "iron", 0, 0.47, 0.02, 0.45, 0.08, 0.04),
            box("foot_b", "iron", 0, -0.47, 0.02, 0.45, 0.08, 0.04)]


def squat_rack():
    """A power rack of four uprights, open at the front (+y): the J-hooks on the front uprights,
    the safety bars along both sides, the top frame; the barbell is a model of its own."""
    v = [box(f"upright{i}", "iron", sx * 0.55, sy * 0.55, 1.15, 0.08, 0.08, 2.3)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    v += [box("top_front", "iron", 0, 0.55, 2.26, 1.18, 0.08, 0.08),
          box("top_back", "iron", 0, -0.55, 2.26, 1.18, 0.08, 0.08),
          box("top_l", "iron", -0.55, 0, 2.26, 0.08, 1.18, 0.08),
          box("top_r", "iron", 0.55, 0, 2.26, 0.08, 1.18, 0.08),
          box("base_l", "iron", -0.55, 0, 0.03, 0.12, 1.3, 0.06),
          box("base_r", "iron", 0.55, 0, 0.03, 0.12, 1.3, 0.06),
          box("safety_l", "chrome", -0.55, 0.05, 0.75, 0.05, 1.35, 0.05),
          box("safety_r", "chrome", 0.55, 0.05, 0.75, 0.05, 1.35, 0.05),
          box("hook_l", "machine_red", -0.55, 0.62, 1.33, 0.06, 0.08, 0.1),
          box("hook_r", "machine_red", 0.55, 0.62, 1.33, 0.06, 0.08, 0.1)]
    return v


def barbell(plates=()):
    """An Olympic barbell along x with its axis at the model's origin: the bar, the two sleeves and
    collars, and any plates (radii, from the inside out) loaded on both sleeves."""
    v = [along_x(cyl("bar", "chrome", 0, 0, 0, 0.014, 1.32)),
         along_x(cyl("sleeve_l", "chrome", -0.9, 0, 0, 0.025, 0.44)),
         along_x(cyl("sleeve_r", "chrome", 0.9, 0, 0, 0.025, 0.44)),
         along_x(cyl("collar_l", "chrome", -0.67, 0, 0, 0.04, 0.03)),
         along_x(cyl("collar_r", "chrome", 0.67, 0, 0, 0.04, 0.03))]
    for k, r in enumerate(plates):
        for side, sx in (("l", -1), ("r", 1)):
            v.append(along_x(cyl(f"plate{k}_{side}", "plate_black", sx * (0.71 + 0.05 * k), 0, 0, r, 0.045)))
    return v


def weight_plate_rack():
    """A plate tree: a post on its base with three pairs of horns (along y), plates stacked on them,
    the big ones low."""
    v = [box("base", "iron", 0, 0, 0.03, 0.65, 0.65, 0.06),
         box("post", "iron", 0, 0, 0.65, 0.08, 0.08, 1.3)]
    for i, (z, r) in enumerate(((0.3, 0.225), (0.72, 0.17), (1.1, 0.12))):
        v.append(along_y(cyl(f"horn{i}", "chrome", 0, 0, z, 0.025, 0.6)))
        for k in range(3 - (i == 2)):
            for side, sy in (("f", 1), ("b", -1)):
                v.append(along_y(cyl(f"plate{i}_{k}{side}", "plate_black", 0, sy * (0.08 + 0.05 * k), z, r, 0.04)))
    return v


def kettlebell(r, c):
    """A kettlebell of body radius r, coloured by its weight: the ball, the flat foot, the handle."""
    return [sph("ball", c, 0, 0, r, r),
            cyl("foot", c, 0, 0, 0.01, r * 0.6, 0.02),
            box("horn_l", c, -r * 0.55, 0, 1.9 * r + 0.04, 0.03, 0.03, 0.12),
            box("horn_r", c, r * 0.55, 0, 1.9 * r + 0.04, 0.03, 0.03, 0.12),
            along_x(cyl("handle", c, 0, 0, 1.9 * r + 0.1, 0.017, r * 1.1 + 0.03))]


def cable_machine(width=2.5):
    """A cable crossover station facing +y: two towers with their weight stacks and pulleys, the
    top beam joining them, the base frame and a pair of handles hanging from the pulleys."""
    v = [box("base", "iron", 0, -0.1, 0.03, width, 0.7, 0.06),
         box("beam", "iron", 0, 0, 2.25, width, 0.12, 0.12)]
    for side, sx in (("l", -1), ("r", 1)):
        x = sx * (width / 2 - 0.2)
        v += [box(f"tower_{side}", "frame_grey", x, 0, 1.12, 0.4, 0.6, 2.24),
              box(f"stack_{side}", "stack_black", x, 0.31, 0.6, 0.24, 0.02, 0.9),
              box(f"guard_{side}", "glass", x, 0.32, 1.1, 0.3, 0.004, 1.8),
              box(f"pulley_arm_{side}", "iron", x - sx * 0.25, 0.15, 1.4, 0.08, 0.08, 1.6),
              along_y(cyl(f"pulley_{side}", "black", x - sx * 0.3, 0.22, 1.5, 0.06, 0.04)),
              box(f"handle_{side}", "pad_black", x - sx * 0.3, 0.3, 1.2, 0.16, 0.03, 0.03)]
    return v + [box("pull_bar", "chrome", 0, 0.1, 2.05, 1.0, 0.03, 0.03)]


def leg_press():
    """A 45-degree leg press: the seat and back rest at the low end (-y), two rails rising to +y,
    the foot plate on its sled and the weight horns loaded with plates."""
    up = "0.785 0 0"
    return [box("base", "frame_grey", 0, 0, 0.08, 1.1, 2.2, 0.16),
            box("seat", "pad_black", 0, -0.6, 0.45, 0.6, 0.5, 0.1),
            box("seat_post", "iron", 0, -0.6, 0.28, 0.12, 0.12, 0.3),
            turned(box("back_rest", "pad_black", 0, -0.9, 0.7, 0.6, 0.1, 0.6), "-0.5 0 0"),
            turned(box("rail_l", "iron", -0.4, 0.45, 0.85, 0.08, 1.6, 0.08), up),
            turned(box("rail_r", "iron", 0.4, 0.45, 0.85, 0.08, 1.6, 0.08), up),
            box("strut", "iron", 0, 0.95, 0.62, 1.0, 0.08, 1.1),
            turned(box("foot_plate", "frame_grey", 0, 0.3, 0.95, 0.8, 0.06, 0.7), up),
            along_x(cyl("horn_l", "chrome", -0.52, 0.45, 1.05, 0.025, 0.25)),
            along_x(cyl("horn_r", "chrome", 0.52, 0.45, 1.05, 0.025, 0.25)),
            along_x(cyl("plate_l", "plate_black", -0.52, 0.45, 1.05, 0.225, 0.05)),
            along_x(cyl("plate_r", "plate_black", 0.52, 0.45, 1.05, 0.225, 0.05)),
            box("handle_l", "chrome", -0.38, -0.5, 0.55, 0.04, 0.35, 0.04),
            box("handle_r", "chrome", 0.38, -0.5, 0.55, 0.04, 0.35, 0.04)]


def mirror(width, height):
    """A wall mirror looking along -y (the wall behind it at +y), centred on the model's origin."""
    return [box("frame", "steel", 0, 0, 0, width, 0.02, height),
            box("glass", "mirror_glass", 0, -0.011, 0, width - 0.04, 0.002, height - 0.04)]


def exercise_mat():
    """A rubber exercise mat laid flat, 0.6 m x 1.8 m."""
    return [box("mat", "mat_blue", 0, 0, 0.006, 0.6, 1.8, 0.012)]


def foam_roller(c="roller_black"):
    """A foam roller lying along x on the floor or a mat."""
    return [along_x(cyl("roller", c, 0, 0, 0.075, 0.075, 0.45))]


def exercise_ball(c="ball_green", r=0.33):
    """An inflatable exercise ball on the floor."""
    return [sph("ball", c, 0, 0, r, r)]


def locker():
    """A two-tier locker column, 0.4 m wide, doors at the front (+y) with vents and handles."""
    v = [box("body", "locker_grey", 0, 0, 0.95, 0.4, 0.5, 1.9),
         box("plinth", "iron", 0, 0, 0.04, 0.4, 0.48, 0.08),
         box("seam", "iron", 0, 0.251, 0.98, 0.38, 0.004, 0.01)]
    for i, z in enumerate((0.55, 1.45)):
        v += [box(f"handle{i}", "chrome", 0.13, 0.255, z, 0.03, 0.01, 0.1),
              box(f"vent{i}", "iron", 0, 0.252, z + 0.3, 0.2, 0.004, 0.08),
              box(f"number{i}", "white", 0, 0.252, z + 0.15, 0.06, 0.004, 0.04)]
    return v


def changing_bench(length=1.8):
    """A changing-room bench along y: three wooden slats on two steel frames."""
    v = [box(f"slat{i}", "slat_wood", -0.13 + 0.13 * i, 0, 0.44, 0.1, length, 0.03) for i in range(3)]
    for side, sy in (("f", 1), ("b", -1)):
        y = sy * (length / 2 - 0.15)
        v += [box(f"leg_{side}l", "steel", -0.16, y, 0.21, 0.04, 0.04, 0.42),
              box(f"leg_{side}r", "steel", 0.16, y, 0.21, 0.04, 0.04, 0.42),
              box(f"rail_{side}", "steel", 0, y, 0.41, 0.4, 0.04, 0.03)]
    return v


def shower():
    """A shower stall open to the front (+y): the tray, tiled back and side panels, the mixer, the
    riser and its head, the curtain on its rail half drawn."""
    return [box("tray", "tile_white", 0, 0, 0.03, 0.95, 1.0, 0.06),
            box("back", "tile_blue", 0, -0.49, 1.05, 0.95, 0.02, 2.1),
            box("side_l", "tile_white", -0.475, 0, 1.05, 0.04, 1.0, 2.1),
            box("side_r", "tile_white", 0.475, 0, 1.05, 0.04, 1.0, 2.1),
            box("mixer", "chrome", 0, -0.47, 1.1, 0.14, 0.03, 0.12),
            cyl("riser", "chrome", 0, -0.46, 1.55, 0.012, 0.9),
            turned(cyl("head", "chrome", 0, -0.38, 2.0, 0.08, 0.02), "0.5 0 0"),
            box("curtain_rail", "chrome", 0, 0.48, 2.0, 0.95, 0.02, 0.02),
            box("curtain", "curtain", -0.25, 0.48, 1.15, 0.45, 0.02, 1.65)]


def sink():
    """A wall-hung washbasin (the wall at -y) with its tap and the trap below."""
    return [box("basin", "ceramic", 0, 0.02, 0.82, 0.55, 0.42, 0.16),
            box("bowl", "steel", 0, 0.04, 0.9, 0.42, 0.3, 0.02),
            cyl("trap", "chrome", 0, -0.1, 0.55, 0.025, 0.4),
            cyl("tap", "chrome", 0, -0.13, 1.0, 0.015, 0.16),
            turned(cyl("spout", "chrome", 0, -0.06, 1.07, 0.012, 0.14), "1.5708 0 0")]


def water_fountain():
    """A wall drinking fountain with a bottle filler above it (the wall at -y)."""
    return [box("bowl_body", "steel", 0, 0.05, 0.85, 0.45, 0.4, 0.3),
            box("bowl", "chrome", 0, 0.08, 1.0, 0.36, 0.28, 0.01),
            cyl("bubbler", "chrome", 0.08, 0.1, 1.04, 0.015, 0.06),
            box("filler", "steel", 0, -0.12, 1.45, 0.4, 0.1, 0.6),
            box("filler_bay", "black", 0, -0.065, 1.35, 0.26, 0.004, 0.3),
            box("filler_sign", "bin_blue", 0, -0.065, 1.65, 0.2, 0.004, 0.08)]


def towel_bin():
    """A bin for used towels: a blue drum with towels piled at its mouth."""
    return [cyl("drum", "bin_blue", 0, 0, 0.4, 0.28, 0.8),
            cyl("rim", "iron", 0, 0, 0.8, 0.29, 0.03),
            sph("towels", "towel_white", 0, 0, 0.78, 0.2),
            box("towel", "towel_white", 0.15, 0.1, 0.7, 0.25, 0.02, 0.3)]


def fire_extinguisher():
    """A red extinguisher on its wall bracket (the wall at -y): body, head, hose and handle."""
    return [box("bracket", "iron", 0, -0.08, 0.85, 0.1, 0.02, 0.3),
            cyl("body", "extinguisher_red", 0, 0, 0.8, 0.08, 0.5),
            sph("shoulder", "extinguisher_red", 0, 0, 1.05, 0.08),
            cyl("head", "black", 0, 0, 1.15, 0.025, 0.08),
            box("handle", "black", 0, 0.04, 1.19, 0.03, 0.12, 0.02),
            turned(cyl("hose", "black", 0.07, 0.03, 1.0, 0.012, 0.3), "0 0.3 0")]


def defibrillator():
    """A wall cabinet (the wall at -y) with an AED behind its glass door and the green sign above."""
    return [box("cabinet", "white", 0, 0, 1.35, 0.4, 0.18, 0.45),
            box("unit", "aed_green", 0, 0.01, 1.32, 0.26, 0.1, 0.3),
            box("handle", "black", 0, 0.01, 1.49, 0.1, 0.04, 0.03),
            box("door", "glass", 0, 0.091, 1.35, 0.36, 0.004, 0.4),
            box("sign", "aed_green", 0, 0.0, 1.72, 0.32, 0.02, 0.16),
            box("sign_heart", "white", 0, 0.011, 1.72, 0.08, 0.002, 0.08)]


def walls():
    """The outer walls with the main entrance; the lobby's east wall and its north partition with
    the turnstile opening; the changing rooms' south wall with two doorways, the partition between
    them and their east wall; the stretching corner and the hall stay open to each other."""
    v, wall = base.wall_builder(H, T)
    wall(0, 0, EX0, 0); wall(EX1, 0, W, 0); wall(EX0, 0, EX1, 0, 2.3, H)
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    wall(XW, 0, XW, LY, c="partition")
    wall(0, LY, GATE0, LY, c="partition"); wall(GATE1, LY, XW, LY, c="partition")
    wall(GATE0, LY, GATE1, LY, 2.3, H, c="partition")
    (m0, m1), (f0, f1) = MEN_DOOR, WOMEN_DOOR
    wall(0, CY, m0, CY, c="partition"); wall(m1, CY, f0, CY, c="partition"); wall(f1, CY, XW, CY, c="partition")
    wall(m0, CY, m1, CY, 2.1, H, c="partition"); wall(f0, CY, f1, CY, 2.1, H, c="partition")
    wall(XC, CY, XC, D, c="partition")
    wall(XW, CY, XW, D, c="partition")
    return v


def lobby(out):
    """The entrance doors, reception facing them, the sofa on the west wall, the turnstiles."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("door_1", (EX0 + 0.04, 0.47, 0, HALF), base.door())  # two leaves swung open into the lobby
    add("door_2", (EX1 - 0.04, 0.47, 0, HALF), base.door())
    add("window_1", (5.0, T / 2 + 0.02, 1.6, 0), base.window())
    # the desk along y east of the way in, members on its west side, the clerk's chair behind it
    add("reception_desk", (5.7, 2.3, 0, HALF), reception_desk())
    add("office_chair", (6.45, 2.3, 0, HALF), base.office_chair())
    add("wall_clock_1", (XW - T / 2 - 0.02, 2.3, 2.4, -HALF), base.wall_clock())
    add("sofa", (T / 2 + 0.48, 2.5, 0, -HALF), base.sofa())
    add("potted_plant_1", (0.45, 0.45, 0, 0), base.plant())
    add("potted_plant_2", (0.45, 4.0, 0, 0), base.plant())
    add("potted_plant_3", (6.5, 0.5, 0, 0), base.plant())
    add("fire_extinguisher_1", (EX1 + 0.35, T / 2 + 0.1, 0, 0), fire_extinguisher())
    add("trash_can_1", (4.2, 0.35, 0, 0), base.trash_can())
    # the turnstiles in the north partition's opening, passed northwards; the wide lane east of
    # them (x 4.5..GATE1) is the open accessible gate
    add("turnstile_1", (GATE0 + 0.2, LY, 0, 0), turnstile())
    add("turnstile_2", (GATE0 + 1.05, LY, 0, 0), turnstile())
    add("defibrillator", (5.82, LY + T / 2 + 0.09, 0, 0), defibrillator())


def stretching(out):
    """The stretching corner north of the lobby: mats on the floor, rollers, balls, a wall mirror;
    the water fountain and the towel bin outside the changing rooms."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    for i, x in enumerate((0.6, 1.35, 2.1, 2.85), 1):
        add(f"exercise_mat_{i}", (x, 6.4, 0, 0), exercise_mat())
    add("foam_roller_1", (0.6, 5.8, 0.012, 0), foam_roller())
    add("foam_roller_2", (2.1, 5.8, 0.012, 0), foam_roller("roller_orange"))
    add("foam_roller_3", (2.6, 7.95, 0, 0), foam_roller())
    add("exercise_ball_1", (0.5, 7.95, 0, 0), exercise_ball())
    add("exercise_ball_2", (1.3, 7.95, 0, 0), exercise_ball("ball_grey"))
    add("exercise_ball_3", (3.6, 7.95, 0, 0), exercise_ball("ball_green", 0.28))
    add("mirror_1", (T / 2 + 0.012, 6.5, 1.3, HALF), mirror(3.0, 1.9))
    add("water_fountain_1", (5.7, CY - T / 2 - 0.2, 0, PI), water_fountain())
    add("towel_bin_1", (6.55, CY - T / 2 - 0.35, 0, 0), towel_bin())
    add("trash_can_2", (5.0, CY - T / 2 - 0.25, 0, 0), base.trash_can())


def changing_room(out, k, x_wall, x_part, door_hinge):
    """One changing room (x between its outer wall x_wall and the partition x_part, y CY..D): the
    door swung in, lockers along the outer wall, the bench in the middle, three showers against
    the north wall, the sink with its mirror on the partition."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    s = 1 if x_part > x_wall else -1  # from the outer wall towards the partition
    add(f"door_{2 + k}", (door_hinge, CY + 0.47, 0, HALF), base.door())
    for i in range(7):
        add(f"locker_{7 * (k - 1) + i + 1}", (x_wall + s * (T / 2 + 0.31), 9.1 + 0.41 * i, 0, -s * HALF), locker())
    add(f"bench_{k}", (x_wall + s * 1.5, 10.3, 0, 0), changing_bench())
    for i in range(3):
        add(f"shower_{3 * (k - 1) + i + 1}", (x_wall + s * (0.55 + 0.96 * i), D - T / 2 - 0.51, 0, PI), shower())
    add(f"sink_{k}", (x_part - s * (T / 2 + 0.23), 11.3, 0, s * HALF), sink())
    add(f"mirror_{1 + k}", (x_part - s * (T / 2 + 0.012), 11.3, 1.55, -s * HALF), mirror(0.6, 0.8))
    add(f"towel_bin_{1 + k}", (x_part - s * 0.4, 12.4, 0, 0), towel_bin())


def cardio(out):
    """The cardio area along the south windows: treadmills facing the windows with televisions
    above, exercise bikes behind them, elliptical trainers and rowing machines to the east."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    for i, x in enumerate((8.6, 11.2, 14.0, 17.0, 19.0), 2):
        add(f"window_{i}", (x, T / 2 + 0.02, 1.6, 0), base.window())
    add("window_7", (W - T / 2 - 0.02, 2.6, 1.6, HALF), base.window())
    for i, x in enumerate((7.9, 9.0, 10.1, 11.2, 12.3), 1):
        add(f"treadmill_{i}", (x, 1.7, 0, PI), treadmill())
    add("television_1", (9.55, T / 2 + 0.08, 2.65, 0), television())
    add("television_2", (15.5, T / 2 + 0.08, 2.65, 0), television())
    for i, x in enumerate((8.3, 9.4, 10.5, 11.6), 1):
        add(f"exercise_bike_{i}", (x, 4.35, 0, PI), exercise_bike())
    for i, x in enumerate((13.7, 14.6, 15.5), 1):
        add(f"elliptical_trainer_{i}", (x, 1.75, 0, PI), elliptical_trainer())
    for i, x in enumerate((17.3, 18.25, 19.2), 1):
        add(f"rowing_machine_{i}", (x, 2.05, 0, PI), rowing_machine())
    add("towel_bin_4", (13.2, 4.9, 0, 0), towel_bin())
    add("trash_can_3", (W - 0.35, 5.3, 0, 0), base.trash_can())
    add("fire_extinguisher_2", (W - T / 2 - 0.1, 4.4, 0, HALF), fire_extinguisher())
    add("wall_clock_2", (W - T / 2 - 0.02, 4.4, 2.5, -HALF), base.wall_clock())
    add("potted_plant_4", (W - 0.45, 0.45, 0, 0), base.plant())


def free_weights(out):
    """The free-weights area in the north of the hall."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("mirror_4", (12.9, D - T / 2 - 0.012, 1.3, 0), mirror(5.8, 1.9))
    # two dumbbell racks against the north wall, their fronts to the south, 16 dumbbells each
    n = 0
    for rack, x in enumerate((11.4, 14.2), 1):
        y = D - T / 2 - 0.36
        add(f"dumbbell_rack_{rack}", (x, y, 0, PI), dumbbell_rack())
        for tier, (ty, tz) in enumerate(DUMBBELL_TIERS):
            for j in range(8):
                r = 0.05 + 0.005 * (j // 2) + 0.02 * tier
                lx = -1.0 + 0.285 * j
                wx, wy = at(x, y, PI, lx, ty)
                n += 1
                add(f"dumbbell_{n}", (wx, wy, tz, PI + HALF), dumbbell(r))
    # the benches in front of the racks, facing the mirror; a pair of dumbbells by the first
    add("weight_bench_1", (11.4, 11.7, 0, 0), weight_bench())
    add("weight_bench_2", (14.2, 11.7, 0, 0), weight_bench())
    add(f"dumbbell_{n + 1}", (11.95, 11.9, 0, 0), dumbbell(0.06))
    add(f"dumbbell_{n + 2}", (11.95, 11.6, 0, 0), dumbbell(0.06))
    # kettlebells in a row on the floor along the north wall, light to heavy
    for i, (r, c) in enumerate(((0.085, "kb_pink"), (0.095, "kb_blue"), (0.105, "kb_yellow"),
                                (0.11, "kb_purple"), (0.12, "kb_green"), (0.13, "kb_red")), 1):
        add(f"kettlebell_{i}", (15.9 + 0.38 * i, D - T / 2 - 0.3, 0, 0), kettlebell(r, c))
    # two squat racks on the east wall, open to the west, a loaded barbell in each one's hooks;
    # the plate rack between them, a bench in the second rack for pressing
    for k, y in enumerate((8.2, 11.2), 1):
        x = W - T / 2 - 0.65
        add(f"squat_rack_{k}", (x, y, 0, HALF), squat_rack())
        bx, by = at(x, y, HALF, 0, 0.62)
        add(f"barbell_{k}", (bx, by, 1.41, HALF), barbell((0.225,) if k == 1 else (0.225, 0.17)))
    add("weight_bench_3", (W - T / 2 - 0.9, 11.2, 0, HALF), weight_bench())
    add("weight_plate_rack_1", (W - T / 2 - 0.45, 9.7, 0, 0), weight_plate_rack())
    # a barbell loaded on the floor for deadlifts and the second plate rack beside it
    add("barbell_3", (15.6, 8.6, 0.225, HALF), barbell((0.225, 0.225)))
    add("weight_plate_rack_2", (16.6, 7.0, 0, 0), weight_plate_rack())
    # the cable machine on the changing rooms' east wall, facing east; the leg press north of it
    add("cable_machine", (XW + T / 2 + 0.45, 10.4, 0, -HALF), cable_machine())
    add("leg_press", (8.7, 12.7, 0, 0), leg_press())
    add("water_fountain_2", (W - T / 2 - 0.2, 13.0, 0, HALF), water_fountain())
    add("trash_can_4", (W - 0.35, 12.2, 0, 0), base.trash_can())
    add("fire_extinguisher_3", (W - T / 2 - 0.1, 6.6, 0, HALF), fire_extinguisher())
    add("potted_plant_5", (XW + 0.5, 13.5, 0, 0), base.plant())


def main():
    out = base.shell(walls(), "floor_gym", "gym_floor", W, D, H)
    lobby(out)
    stretching(out)
    changing_room(out, 1, 0.0, XC, MEN_DOOR[0] + 0.04)
    changing_room(out, 2, XW, XC, WOMEN_DOOR[1] - 0.04)
    cardio(out)
    free_weights(out)
    lights = [base.point_light(name, x, y, H - 0.25, "0.8 0.8 0.78")
              for name, x, y in (("light_lobby", 3.5, 2.2), ("light_stretching", 3.5, 6.5),
                                 ("light_changing_1", 1.75, 11.2), ("light_changing_2", 5.25, 11.2),
                                 ("light_cardio_w", 10.0, 2.8), ("light_cardio_e", 16.5, 2.8),
                                 ("light_weights_w", 10.0, 10.0), ("light_weights_e", 16.5, 10.0))]
    print(base.world_sdf("semsplat_gym", """The semsplat gym: a fitness centre of 20 m x 14 m (the lobby with the entrance, reception
     and the turnstiles in the south-west; the stretching corner north of it and two changing rooms
     with lockers, benches, showers and sinks in the north-west; the open hall in the east with the
     cardio area along the south windows and the free-weights area in the north) for measuring on
     a world nobody tuned on. Generated by gym_models/make_gym.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
