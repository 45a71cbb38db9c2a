#!/usr/bin/env python3
"""Writes data/worlds/ward.world: a hospital ward of 10 m x 8 m (a four-bed bay in the north with
privacy curtains between the beds, a hand-washing sink on the west wall; a corridor in the south
behind a partition, with the nurses' station, the medicine cart, a stretcher and a wheelchair) for
measuring the semantic stack on a world nobody tuned on. Every model is inline (boxes, cylinders,
spheres), so the world needs no model path. Model names are what a world author would type; the
class is the name less its _<number> ("patient_bed", not "hospital_bed": synth drops "hospital"
as a model-pack prefix). The primitives and the SDF writing are the office generator's.
Run: python3 data/worlds/ward_models/make_ward.py > data/worlds/ward.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document)

W, D, H = 10.0, 8.0, 2.8   # room width (x), depth (y), wall height
T = 0.1                    # wall thickness
YP = 2.6                   # the partition between the corridor (south) and the bay (north)

base.COL.update({
    "vinyl": "0.62 0.7 0.66", "mint": "0.72 0.86 0.8", "curtain": "0.45 0.62 0.75",
    "mattress": "0.92 0.94 0.96", "bed_frame": "0.85 0.86 0.88", "rubber": "0.1 0.1 0.1",
    "oxygen_green": "0.2 0.55 0.3", "iv_bag": "0.85 0.92 0.95", "counter": "0.7 0.55 0.4",
    "steel": "0.78 0.8 0.82", "cart_blue": "0.3 0.45 0.7", "pedal_bin": "0.85 0.2 0.15",
    "screen_green": "0.1 0.35 0.25", "seat_blue": "0.25 0.35 0.6", "ceramic": "0.96 0.96 0.97",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned = base.turned


def wheel(name, c, x, y, z, r, width):  # axle along x
    return turned(cyl(name, c, x, y, z, r, width), "0 1.5708 0")


def castors(hx, hy, r=0.05):
    return [sph(f"castor{i}", "rubber", sx * hx, sy * hy, r, r)
            for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


# ---- the things (local frames: x right, y forward, z up; a bed's head is at +y) ----
def patient_bed():
    v = [box("frame", "bed_frame", 0, 0, 0.5, 0.95, 2.1, 0.12),
         box("mattress", "mattress", 0, -0.05, 0.64, 0.9, 1.95, 0.16),
         box("pillow", "mattress", 0, 0.8, 0.76, 0.6, 0.3, 0.1),
         box("headboard", "bed_frame", 0, 1.04, 0.8, 0.95, 0.04, 0.6),
         box("footboard", "bed_frame", 0, -1.04, 0.7, 0.95, 0.04, 0.4),
         box("rail_l", "steel", -0.49, 0.3, 0.85, 0.02, 0.9, 0.2),
         box("rail_r", "steel", 0.49, 0.3, 0.85, 0.02, 0.9, 0.2)]
    return v + legs("steel", 0.4, 0.95, 0.45, 0.05) + castors(0.4, 0.95)


def bedside_cabinet():
    return [box("body", "mint", 0, 0, 0.42, 0.5, 0.45, 0.84),
            box("drawer_seam", "steel", 0, 0.226, 0.62, 0.46, 0.005, 0.01),
            box("handle", "steel", 0, 0.235, 0.7, 0.14, 0.02, 0.02)]


def overbed_table():
    # a top on one column at the side, a base that rolls under the bed
    return [box("top", "counter", 0, 0, 0.95, 0.9, 0.4, 0.03),
            box("column", "steel", -0.4, 0, 0.48, 0.05, 0.05, 0.92),
            box("base", "steel", -0.4, 0, 0.04, 0.08, 0.6, 0.04)] + \
           [sph(f"castor{i}", "rubber", -0.4, s * 0.28, 0.03, 0.03) for i, s in enumerate((-1, 1))]


def iv_stand():
    return [cyl("base", "steel", 0, 0, 0.03, 0.28, 0.04),
            cyl("pole", "steel", 0, 0, 1.0, 0.015, 1.95),
            box("hook_bar", "steel", 0, 0, 1.95, 0.3, 0.02, 0.02),
            box("bag", "iv_bag", 0.12, 0, 1.78, 0.12, 0.04, 0.2)]


def privacy_curtain(length):
    return [box("fabric", "curtain", 0, 0, 1.2, 0.02, length, 1.9),
            box("rail", "steel", 0, 0, 2.25, 0.04, length + 0.1, 0.03)]


def visitor_chair():
    return [box("seat", "seat_blue", 0, 0, 0.45, 0.5, 0.48, 0.07),
            box("back", "seat_blue", 0, -0.22, 0.78, 0.5, 0.05, 0.5),
            box("arm_l", "steel", -0.26, 0, 0.64, 0.03, 0.45, 0.03),
            box("arm_r", "steel", 0.26, 0, 0.64, 0.03, 0.45, 0.03)] + legs("steel", 0.22, 0.2, 0.42, 0.03)


def wheelchair():
    return [box("seat", "black", 0, 0, 0.5, 0.45, 0.45, 0.05),
            box("back", "black", 0, -0.24, 0.78, 0.45, 0.03, 0.45),
            box("footrest", "steel", 0, 0.38, 0.12, 0.4, 0.15, 0.02),
            wheel("wheel_l", "rubber", -0.3, -0.08, 0.3, 0.3, 0.04),
            wheel("wheel_r", "rubber", 0.3, -0.08, 0.3, 0.3, 0.04),
            sph("castor_l", "rubber", -0.2, 0.3, 0.06, 0.06), sph("castor_r", "rubber", 0.2, 0.3, 0.06, 0.06),
            box("handle_l", "steel", -0.21, -0.28, 1.0, 0.03, 0.12, 0.03),
            box("handle_r", "steel", 0.21, -0.28, 1.0, 0.03, 0.12, 0.03)]


def patient_monitor():
    # a screen on a rolling stand beside the bed head
    return [cyl("base", "steel", 0, 0, 0.03, 0.25, 0.04),
            cyl("pole", "steel", 0, 0, 0.6, 0.02, 1.15),
            box("case", "grey_plastic", 0, 0, 1.32, 0.36, 0.14, 0.3),
            box("screen", "screen_green", 0, 0.071, 1.33, 0.3, 0.004, 0.22)]


def oxygen_tank():
    return [cyl("body", "oxygen_green", 0, 0, 0.5, 0.1, 0.9),
            sph("shoulder", "oxygen_green", 0, 0, 0.95, 0.1),
            cyl("valve", "steel", 0, 0, 1.1, 0.025, 0.12),
            box("trolley", "dark_metal", 0, 0, 0.03, 0.3, 0.25, 0.04)]


def nurses_station():
    # a counter with a raised ledge to the corridor and the working top behind it
    return [box("front", "counter", 0, 0.3, 0.55, 2.6, 0.1, 1.1),
            box("ledge", "light_wood", 0, 0.3, 1.12, 2.7, 0.3, 0.04),
            box("worktop", "light_wood", 0, -0.05, 0.75, 2.6, 0.6, 0.04),
            box("side_l", "counter", -1.3, -0.05, 0.37, 0.04, 0.6, 0.75),
            box("side_r", "counter", 1.3, -0.05, 0.37, 0.04, 0.6, 0.75),
            box("screen", "black", -0.6, -0.1, 1.0, 0.5, 0.04, 0.32)]


def medicine_cart():
    v = [box("body", "cart_blue", 0, 0, 0.55, 0.65, 0.48, 0.9),
         box("top", "grey_plastic", 0, 0, 1.02, 0.7, 0.52, 0.04),
         box("handle", "steel", 0, -0.28, 0.95, 0.5, 0.03, 0.03)]
    v += [box(f"drawer{i}", "white", 0, 0.243, 0.3 + 0.2 * i, 0.55, 0.005, 0.16) for i in range(4)]
    return v + castors(0.26, 0.18)


def stretcher():
    return [box("deck", "steel", 0, 0, 0.8, 0.65, 1.95, 0.06),
            box("pad", "mattress", 0, 0, 0.87, 0.6, 1.9, 0.08),
            box("rail_l", "steel", -0.34, 0, 0.97, 0.02, 1.4, 0.12),
            box("rail_r", "steel", 0.34, 0, 0.97, 0.02, 1.4, 0.12)] + \
        legs("steel", 0.25, 0.8, 0.77, 0.05) + castors(0.25, 0.8)


def sink():
    return [box("basin", "ceramic", 0, 0, 0.82, 0.55, 0.42, 0.18),
            box("bowl", "steel", 0, 0.02, 0.9, 0.42, 0.3, 0.02),
            box("pedestal", "ceramic", 0, -0.08, 0.37, 0.2, 0.2, 0.74),
            cyl("tap", "steel", 0, -0.15, 1.0, 0.015, 0.16),
            turned(cyl("spout", "steel", 0, -0.08, 1.07, 0.012, 0.14), "1.5708 0 0")]


def hand_sanitizer():
    # wall-mounted dispenser; the wall is behind (-y)
    return [box("body", "white", 0, 0, 1.25, 0.12, 0.1, 0.24),
            box("nozzle", "grey_plastic", 0, 0.03, 1.11, 0.04, 0.04, 0.04)]


def waste_bin():
    return [cyl("body", "pedal_bin", 0, 0, 0.3, 0.16, 0.6),
            cyl("lid", "steel", 0, 0, 0.61, 0.165, 0.02),
            box("pedal", "dark_metal", 0, 0.17, 0.03, 0.12, 0.06, 0.02)]


def walls():
    v, wall = base.wall_builder(H, T)
    # outer walls; the corridor's entrance (y 0.6..1.6) in the west wall
    wall(0, 0, W, 0); wall(0, D, W, D); wall(W, 0, W, D)
    wall(0, 0, 0, 0.6); wall(0, 1.6, 0, D); wall(0, 0.6, 0, 1.6, 2.1, H)
    # the bay's partition, a wide doorway (x 4.4..5.8, for beds) into the corridor
    wall(0, YP, 4.4, YP, c="partition"); wall(5.8, YP, W, YP, c="partition")
    wall(4.4, YP, 5.8, YP, 2.2, H, c="partition")
    return v


def main():
    out = base.shell(walls(), "floor_ward", "vinyl", W, D, H)
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # the bay: four beds, heads to the north wall, a cabinet to the right of each head
    beds = [1.3, 3.7, 6.1, 8.5]
    yb = D - T / 2 - 1.07
    for i, x in enumerate(beds, 1):
        add(f"patient_bed_{i}", (x, yb, 0, 0), patient_bed())
        add(f"bedside_cabinet_{i}", (x + 0.8, D - 0.35, 0, 3.1416), bedside_cabinet())
    for i, x in enumerate((2.5, 4.9, 7.3), 1):  # curtains between neighbouring beds
        add(f"privacy_curtain_{i}", (x, D - 1.25, 0, 0), privacy_curtain(2.4))
    add("patient_monitor_1", (0.45, D - 0.45, 0, 0), patient_monitor())
    add("patient_monitor_2", (5.3, D - 0.45, 0, 0), patient_monitor())
    add("iv_stand_1", (0.5, yb - 0.4, 0, 0), iv_stand())
    add("iv_stand_2", (2.9, yb + 0.3, 0, 0), iv_stand())
    add("iv_stand_3", (7.7, yb - 0.2, 0, 0), iv_stand())
    add("overbed_table_1", (3.85, yb - 0.5, 0, 3.1416), overbed_table())  # column by the bed
    add("overbed_table_2", (8.65, yb - 0.5, 0, 3.1416), overbed_table())
    for i, x in enumerate((1.9, 4.3, 9.2), 1):  # visitors sit by the foot of the bed
        add(f"visitor_chair_{i}", (x, yb - 1.55, 0, 0), visitor_chair())
    add("oxygen_tank_1", (6.95, yb - 0.7, 0, 0), oxygen_tank())
    # hand washing on the west wall of the bay, sanitizer by the bay's doorway too
    add("sink", (T / 2 + 0.22, 3.9, 0, -1.5708), sink())
    add("hand_sanitizer_1", (T / 2 + 0.06, 3.3, 0, -1.5708), hand_sanitizer())
    add("hand_sanitizer_2", (4.2, YP + T / 2 + 0.06, 0, 0), hand_sanitizer())
    add("waste_bin_1", (0.3, 4.6, 0, 0), waste_bin())
    add("window_1", (W - T / 2 - 0.02, 4.5, 1.5, 1.5708), base.window())
    add("window_2", (W - T / 2 - 0.02, 6.3, 1.5, 1.5708), base.window())
    add("door_1", (5.78, YP + 0.47, 0, 1.5708), base.door())  # the bay's, hinged at x 5.8
    # the corridor: the nurses' station on the east, the carts and chairs along the walls
    add("nurses_station", (8.2, 1.2, 0, 0), nurses_station())
    add("waste_bin_2", (6.6, 0.4, 0, 0), waste_bin())
    add("medicine_cart", (5.6, 0.45, 0, 0), medicine_cart())
    add("stretcher", (2.6, 2.05, 0, 1.5708), stretcher())
    add("wheelchair", (4.0, 0.6, 0, 3.1416), wheelchair())
    add("oxygen_tank_2", (0.35, 2.25, 0, 0), oxygen_tank())
    add("door_2", (0.47, 1.57, 0, 0), base.door())  # the corridor's entrance, swung open
    lights = [base.point_light(name, x, y, 2.55, "0.75 0.75 0.73")
              for name, x, y in (("light_bay_w", 2.5, 5.8), ("light_bay_e", 7.3, 5.8),
                                 ("light_corridor_w", 2.5, 1.3), ("light_corridor_e", 7.5, 1.3))]
    print(base.world_sdf("semsplat_ward", """The semsplat ward: a hospital ward of 10 m x 8 m (a four-bed bay in the north with privacy
     curtains, a sink on its west wall; a corridor in the south with the nurses' station, the
     medicine cart, a stretcher and a wheelchair) for measuring on a world nobody tuned on.
     Generated by ward_models/make_ward.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
