#!/usr/bin/env python3
"""Writes data/worlds/hotel.world: a hotel room of 5 m x 7.5 m with its en-suite bathroom and a
small entrance hall (the bathroom in the south-west: bathtub along the south wall, a shower
cubicle, the toilet, a sink under a mirror, a towel rail; the entrance hall in the south-east
behind the room door: an open wardrobe with the room safe in it, an ironing board, the luggage
rack, the minibar with a coffee maker on it; the bedroom in the north: a double bed with a
nightstand and a bedside lamp either side, a desk with its chair under the wall-mounted TV, an
armchair by the windows) for measuring the semantic stack on a world nobody tuned on. Every
model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names are
what a world author would type; the class is the name less its _<number>. The primitives and
the SDF writing are the office generator's.
Run: python3 data/worlds/hotel_models/make_hotel.py > data/worlds/hotel.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document)
from make_ward import turned  # noqa: E402  (rotated visuals)

W, D, H = 5.0, 7.5, 2.6    # whole suite width (x), depth (y), wall height
T = 0.1                    # wall thickness
XB = 2.6                   # the bathroom's east wall (bathroom x 0..XB, y 0..YP)
YP = 3.2                   # the partition between the bathroom/hall (south) and the bedroom
EX0, EX1 = 3.4, 4.3        # the room door's opening in the south wall
BY0, BY1 = 2.2, 3.0        # the bathroom door's opening in its east wall
PX0, PX1 = 3.3, 4.5        # the open passage from the hall into the bedroom

base.COL.update({
    "carpet_hotel": "0.55 0.45 0.38", "tiles": "0.86 0.87 0.88", "ceramic": "0.96 0.96 0.95",
    "chrome": "0.8 0.82 0.85", "linen": "0.97 0.96 0.93", "throw": "0.5 0.15 0.2",
    "walnut": "0.4 0.27 0.17", "shade": "0.95 0.9 0.75", "brass": "0.75 0.6 0.3",
    "screen": "0.05 0.05 0.06", "upholstery": "0.3 0.4 0.35", "mirror": "0.8 0.85 0.9",
    "towel": "0.95 0.95 0.92", "safe_grey": "0.3 0.3 0.32", "board_cover": "0.6 0.7 0.8",
    "minibar_black": "0.12 0.12 0.13", "door_panel": "0.92 0.92 0.9",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs


# ---- the things (local frames: x right, y forward, z up) ----
def bed():
    # a double bed, the headboard at -x (against the west wall), length along x
    return [box("frame", "walnut", 0, 0, 0.2, 2.0, 1.6, 0.3),
            box("mattress", "linen", 0.02, 0, 0.45, 1.95, 1.55, 0.22),
            box("headboard", "walnut", -1.02, 0, 0.75, 0.06, 1.7, 1.1),
            box("pillow_l", "linen", -0.8, -0.4, 0.62, 0.35, 0.6, 0.12),
            box("pillow_r", "linen", -0.8, 0.4, 0.62, 0.35, 0.6, 0.12),
            box("throw", "throw", 0.7, 0, 0.57, 0.5, 1.62, 0.03)]


def nightstand():
    return [box("body", "walnut", 0, 0, 0.27, 0.45, 0.4, 0.5),
            box("top", "walnut", 0, 0, 0.53, 0.48, 0.42, 0.03),
            box("drawer", "brass", 0.23, 0, 0.38, 0.005, 0.12, 0.02)]


def bedside_lamp():
    # stands on a nightstand (z is the nightstand's top)
    return [cyl("base", "brass", 0, 0, 0.02, 0.08, 0.04),
            cyl("stem", "brass", 0, 0, 0.2, 0.012, 0.34),
            cyl("shade", "shade", 0, 0, 0.42, 0.14, 0.2)]


def desk():
    # a writing desk against the wall behind it (+x after the world's yaw), open underneath
    return [box("top", "walnut", 0, 0, 0.74, 1.2, 0.55, 0.04),
            box("modesty", "walnut", 0, 0.25, 0.45, 1.15, 0.03, 0.5)] + \
        legs("walnut", 0.56, 0.23, 0.72, 0.05)


def desk_chair():
    # the back at -y
    return [box("seat", "upholstery", 0, 0, 0.46, 0.45, 0.45, 0.06),
            box("back", "upholstery", 0, -0.21, 0.75, 0.43, 0.05, 0.5)] + \
        legs("walnut", 0.19, 0.19, 0.44, 0.035)


def armchair():
    # deep, upholstered; the back at -y
    return [box("base", "upholstery", 0, 0, 0.22, 0.8, 0.8, 0.3),
            box("cushion", "upholstery", 0, 0.05, 0.42, 0.6, 0.65, 0.1),
            box("back", "upholstery", 0, -0.33, 0.65, 0.8, 0.15, 0.6),
            box("arm_l", "upholstery", -0.34, 0.03, 0.5, 0.12, 0.75, 0.25),
            box("arm_r", "upholstery", 0.34, 0.03, 0.5, 0.12, 0.75, 0.25)]


def tv():
    # a flat screen hung on the wall behind it (+y), facing -y
    return [box("panel", "black", 0, 0, 0, 1.1, 0.05, 0.65),
            box("screen", "screen", 0, -0.026, 0, 1.05, 0.002, 0.6),
            box("bracket", "dark_metal", 0, 0.04, 0, 0.3, 0.04, 0.2)]


def minibar():
    # a small fridge cabinet, the door at -y
    return [box("body", "minibar_black", 0, 0, 0.3, 0.5, 0.5, 0.6),
            box("door", "walnut", 0, -0.255, 0.3, 0.48, 0.01, 0.56),
            box("handle", "chrome", 0.18, -0.27, 0.4, 0.02, 0.02, 0.2)]


def coffee_maker():
    # sits on the minibar (z is its top)
    return [box("base", "black", 0, 0, 0.02, 0.2, 0.24, 0.04),
            box("tower", "black", 0, 0.08, 0.17, 0.2, 0.08, 0.3),
            box("head", "black", 0, 0.0, 0.29, 0.2, 0.2, 0.06),
            cyl("cup", "ceramic", 0, -0.03, 0.08, 0.04, 0.08)]


def luggage_rack():
    # a folding stand with webbing straps across its top
    v = [box(f"rail{i}", "walnut", s * 0.3, 0, 0.5, 0.03, 0.45, 0.03) for i, s in enumerate((-1, 1))]
    v += [box(f"strap{i}", "throw", 0, -0.15 + 0.15 * i, 0.51, 0.6, 0.05, 0.01) for i in range(3)]
    v += [turned(box(f"leg{i}", "walnut", s * 0.3, 0, 0.25, 0.025, 0.025, 0.55), f"{0.5 * t} 0 0")
          for i, (s, t) in enumerate(((-1, 1), (-1, -1), (1, 1), (1, -1)))]
    return v


def wardrobe():
    # an open hotel wardrobe, the open front at -y: sides, back, hat shelf, hanging rail, hangers
    v = [box("side_l", "walnut", -0.5, 0, 1.0, 0.03, 0.6, 2.0),
         box("side_r", "walnut", 0.5, 0, 1.0, 0.03, 0.6, 2.0),
         box("back", "walnut", 0, 0.29, 1.0, 1.0, 0.02, 2.0),
         box("top", "walnut", 0, 0, 2.0, 1.03, 0.6, 0.03),
         box("bottom", "walnut", 0, 0, 0.02, 1.0, 0.6, 0.04),
         box("hat_shelf", "walnut", 0, 0, 1.75, 1.0, 0.55, 0.02),
         turned(cyl("rail", "chrome", 0, 0, 1.65, 0.012, 0.98), "0 1.5708 0")]
    v += [box(f"hanger{i}", "walnut", -0.3 + 0.2 * i, 0, 1.6, 0.01, 0.4, 0.06) for i in range(4)]
    return v


def room_safe():
    # a small safe with a keypad, on the wardrobe's floor, the door at -y
    return [box("body", "safe_grey", 0, 0, 0.15, 0.4, 0.35, 0.26),
            box("door", "dark_metal", 0, -0.176, 0.15, 0.36, 0.005, 0.22),
            box("keypad", "black", 0.1, -0.18, 0.18, 0.08, 0.005, 0.08)]


def ironing_board():
    # folded, standing on its end against the wall behind it (+y)
    return [box("board", "board_cover", 0, 0, 0.66, 0.36, 0.04, 1.3),
            box("legs", "chrome", 0, 0.03, 0.6, 0.3, 0.02, 1.1),
            box("iron_rest", "chrome", 0, 0, 1.33, 0.2, 0.04, 0.05)]


def toilet():
    # the cistern at -y against the wall
    return [box("cistern", "ceramic", 0, -0.28, 0.6, 0.4, 0.18, 0.4),
            box("pedestal", "ceramic", 0, 0.0, 0.2, 0.3, 0.4, 0.4),
            box("bowl", "ceramic", 0, 0.05, 0.38, 0.38, 0.5, 0.06),
            box("seat", "white", 0, 0.07, 0.42, 0.38, 0.46, 0.02),
            box("flush", "chrome", 0, -0.28, 0.81, 0.05, 0.05, 0.02)]


def bathtub():
    # a built-in tub, length along x
    return [box("outer_s", "ceramic", 0, -0.35, 0.28, 1.7, 0.05, 0.56),
            box("outer_n", "ceramic", 0, 0.35, 0.28, 1.7, 0.05, 0.56),
            box("outer_w", "ceramic", -0.83, 0, 0.28, 0.05, 0.75, 0.56),
            box("outer_e", "ceramic", 0.83, 0, 0.28, 0.05, 0.75, 0.56),
            box("bottom", "ceramic", 0, 0, 0.06, 1.6, 0.65, 0.12),
            box("tap", "chrome", -0.78, 0, 0.62, 0.06, 0.06, 0.1)]


def shower():
    # a glass-walled cubicle in a corner: tray, two glass panes, the head on its riser
    return [box("tray", "ceramic", 0, 0, 0.04, 0.9, 0.9, 0.08),
            box("glass_e", "glass", 0.45, 0, 1.05, 0.01, 0.9, 1.95),
            box("glass_s", "glass", 0.05, -0.45, 1.05, 0.8, 0.01, 1.95),
            cyl("riser", "chrome", -0.4, 0.4, 1.3, 0.012, 1.2),
            box("head", "chrome", -0.35, 0.35, 1.92, 0.15, 0.15, 0.03)]


def sink():
    # a vanity counter with a basin, against the wall behind it (+y)
    return [box("vanity", "walnut", 0, 0, 0.4, 0.9, 0.45, 0.8),
            box("counter", "ceramic", 0, 0, 0.82, 0.95, 0.5, 0.04),
            cyl("basin", "ceramic", 0, -0.02, 0.87, 0.18, 0.08),
            cyl("tap", "chrome", 0, 0.17, 0.92, 0.015, 0.16)]


def mirror():
    # hung on the wall behind it (+y)
    return [box("frame", "chrome", 0, 0, 0, 0.85, 0.02, 0.8),
            box("glass", "mirror", 0, -0.011, 0, 0.8, 0.002, 0.75)]


def towel_rail():
    # on the wall behind it (+y): two bars with towels over them
    return [turned(cyl("bar_low", "chrome", 0, -0.06, 1.0, 0.012, 0.6), "0 1.5708 0"),
            turned(cyl("bar_high", "chrome", 0, -0.06, 1.3, 0.012, 0.6), "0 1.5708 0"),
            box("bracket_l", "chrome", -0.3, -0.03, 1.15, 0.02, 0.06, 0.35),
            box("bracket_r", "chrome", 0.3, -0.03, 1.15, 0.02, 0.06, 0.35),
            box("towel", "towel", 0, -0.07, 1.12, 0.5, 0.03, 0.45)]


def room_door():
    # the entrance door, closed in its opening, the peephole and handle inside
    w = EX1 - EX0
    return [box("leaf", "door_panel", 0, 0, 1.02, w - 0.02, 0.05, 2.04),
            cyl("handle", "chrome", w / 2 - 0.1, 0.04, 1.0, 0.015, 0.06),
            sph("peephole", "brass", 0, 0.03, 1.5, 0.015)]


def walls():
    v, wall = base.wall_builder(H, T)
    # the outer walls; the room door's opening in the south wall
    wall(0, 0, EX0, 0); wall(EX1, 0, W, 0); wall(EX0, 0, EX1, 0, 2.1, H)
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    # the bathroom's east wall, with its door's opening
    wall(XB, 0, XB, BY0, c="tiles"); wall(XB, BY1, XB, YP, c="tiles")
    wall(XB, BY0, XB, BY1, 2.1, H, c="tiles")
    # the partition to the bedroom: solid behind the bathroom, an open passage from the hall
    wall(0, YP, XB, YP, c="tiles"); wall(XB, YP, PX0, YP); wall(PX1, YP, W, YP)
    wall(PX0, YP, PX1, YP, 2.2, H)
    return v


def main():
    out = []
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("walls", (0, 0, 0, 0), walls())
    # carpet everywhere, the bathroom's tiles laid on it (their top 5 mm higher)
    add("floor", (0, 0, 0, 0), base.floor_slab("floor_room", "carpet_hotel", W, D) +
        [box("floor_bathroom", "tiles", XB / 2, YP / 2, -0.005, XB, YP, 0.02)])
    add("ceiling", (0, 0, 0, 0), base.ceiling_slab(W, D, H))
    # the room door (closed) and the bathroom door (open into the bathroom, hinged at y BY0)
    add("door_1", ((EX0 + EX1) / 2, T / 2 + 0.03, 0, 0), room_door())
    add("door_2", (XB - 0.47, BY0 + 0.02, 0, 0), base.door())
    # the bathroom: tub along the south wall, shower in the north-west corner, toilet on the
    # west wall, the sink and its mirror on the north wall, the towel rail by the tub
    add("bathtub", (0.92, T / 2 + 0.4, 0, 0), bathtub())
    add("shower", (T / 2 + 0.45, YP - T / 2 - 0.45, 0, 0), shower())
    add("toilet", (T / 2 + 0.38, 1.45, 0, -1.5708), toilet())
    add("sink", (1.55, YP - T / 2 - 0.25, 0, 0), sink())
    add("mirror", (1.55, YP - T / 2 - 0.02, 1.45, 0), mirror())
    add("towel_rail", (XB - T / 2 - 0.02, 1.3, 0, -1.5708), towel_rail())
    # the entrance hall: wardrobe with the safe and the ironing board on the east wall, the
    # luggage rack against the bathroom wall, the minibar with the coffee maker by the door
    xe = W - T / 2
    add("wardrobe", (xe - 0.31, 2.3, 0, -1.5708), wardrobe())
    add("room_safe", (xe - 0.3, 2.3, 0.04, -1.5708), room_safe())
    add("ironing_board", (xe - 0.04, 1.45, 0, -1.5708), ironing_board())
    add("luggage_rack", (XB + T / 2 + 0.3, 1.2, 0, 1.5708), luggage_rack())
    add("minibar", (xe - 0.27, 0.45, 0, -1.5708), minibar())
    add("coffee_maker", (xe - 0.27, 0.45, 0.6, -1.5708), coffee_maker())
    # the bedroom: the bed's head on the west wall, a nightstand and a lamp each side, the desk
    # and the TV above it on the east wall facing the bed, the armchair by the windows
    yb = 5.25
    add("bed", (T / 2 + 1.05, yb, 0, 0), bed())
    for i, y in enumerate((yb - 1.08, yb + 1.08), 1):
        add(f"nightstand_{i}", (T / 2 + 0.25, y, 0, 0), nightstand())
        add(f"bedside_lamp_{i}", (T / 2 + 0.25, y, 0.545, 0), bedside_lamp())
    add("desk", (xe - 0.28, yb, 0, -1.5708), desk())
    add("desk_chair", (xe - 0.8, yb, 0, -1.5708), desk_chair())
    add("tv", (xe - 0.03, yb, 1.45, -1.5708), tv())
    add("armchair", (4.2, D - 0.75, 0, 2.6), armchair())
    for i, x in enumerate((1.6, 3.5), 1):
        add(f"window_{i}", (x, D - T / 2 - 0.02, 1.45, 0), base.window())
    lights = [base.point_light(name, x, y, 2.45, "0.75 0.74 0.7")
              for name, x, y in (("light_bath", 1.3, 1.6), ("light_hall", 3.8, 1.6),
                                 ("light_bed", 1.6, 5.3), ("light_desk", 3.8, 5.6))]
    print(base.world_sdf("semsplat_hotel", """The semsplat hotel room: 5 m x 7.5 m with its en-suite
     bathroom (bathtub, shower, toilet, sink under a mirror, towel rail) and a small entrance hall
     (wardrobe with the room safe, ironing board, luggage rack, minibar with a coffee maker)
     south of the bedroom (double bed between two nightstands with bedside lamps, desk and chair
     under the TV, armchair by the windows) for measuring on a world nobody tuned on. Generated
     by hotel_models/make_hotel.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
