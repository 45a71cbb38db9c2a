#!/usr/bin/env python3
"""Writes data/worlds/salon.world: a hair salon of 11 m x 8 m with a barber's corner (the entrance
in the middle of the south shop front; reception with its desk and the product shelf east of the
door; the waiting area in the south-west with the sofa, coffee table, television, coat rack and a
plant; four styling stations along the north wall, each a counter with a mirror above it and a
styling chair in front, tool trolleys between them and two hood dryers in the north-west corner;
three wash basins on the west wall; the barber's corner in the south-east with two barber chairs
facing mirrors on the east wall and the barber pole; a small staff room behind a partition in the
north-east with lockers, a washing machine, a mini fridge with the microwave on it and a broom) for
measuring the semantic stack on a world nobody tuned on. Every model is inline (boxes, cylinders,
spheres), so the world needs no model path. Model names are what a world author would type; the
class is the name less its _<number>. The primitives and the SDF writing are the office
generator's. Run: python3 data/worlds/salon_models/make_salon.py > data/worlds/salon.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, sofa, locker, plant)
from make_ward import turned, wheel, castors  # noqa: E402  (rotated visuals, wheels, castors)

W, D, H = 11.0, 8.0, 2.8   # salon width (x), depth (y), wall height
T = 0.1                    # wall thickness
EX0, EX1 = 4.6, 5.5        # the entrance in the south wall
SX, SY = 8.0, 5.0          # the staff room: x > SX, y > SY
DX0, DX1 = 8.6, 9.5        # the staff room's doorway in its south partition

base.COL.update({
    "salon_floor": "0.85 0.84 0.82", "leather_black": "0.08 0.08 0.09", "leather_red": "0.6 0.08 0.1",
    "chrome": "0.8 0.82 0.85", "counter_white": "0.94 0.93 0.9", "mirror": "0.75 0.82 0.88",
    "basin_black": "0.12 0.12 0.13", "dryer_hood": "0.9 0.9 0.92", "pole_red": "0.8 0.1 0.1",
    "pole_blue": "0.15 0.25 0.7", "bottle_pink": "0.9 0.5 0.65", "bottle_teal": "0.2 0.6 0.6",
    "bottle_amber": "0.8 0.55 0.2", "screen": "0.1 0.12 0.15", "fridge_white": "0.95 0.96 0.97",
    "broom_head": "0.3 0.25 0.2", "rubber": "0.1 0.1 0.1", "glass_door": "0.55 0.65 0.75",
    "desk_front": "0.35 0.22 0.15",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
BOTTLES = ("bottle_pink", "bottle_teal", "bottle_amber")


# ---- the things (local frames: x right, y forward = the side a person faces, z up) ----
def styling_chair():
    """A hydraulic salon chair: round chrome base, pump column, padded seat, back and arms."""
    return [cyl("base", "chrome", 0, 0, 0.02, 0.3, 0.04),
            cyl("pump", "chrome", 0, 0, 0.25, 0.05, 0.42),
            box("seat", "leather_black", 0, 0, 0.52, 0.52, 0.5, 0.1),
            box("back", "leather_black", 0, -0.24, 0.88, 0.5, 0.07, 0.62),
            box("arm_l", "leather_black", -0.28, 0, 0.68, 0.07, 0.45, 0.06),
            box("arm_r", "leather_black", 0.28, 0, 0.68, 0.07, 0.45, 0.06),
            box("footrest", "chrome", 0, 0.38, 0.2, 0.4, 0.12, 0.02)]


def barber_chair():
    """A heavier reclining barber's chair: red leather, headrest, chrome arms and a footplate."""
    return [cyl("base", "chrome", 0, 0, 0.03, 0.34, 0.06),
            cyl("pump", "chrome", 0, 0, 0.3, 0.07, 0.5),
            box("seat", "leather_red", 0, 0, 0.6, 0.56, 0.55, 0.14),
            turned(box("back", "leather_red", 0, -0.3, 1.0, 0.54, 0.1, 0.7), "-0.2 0 0"),
            box("headrest", "leather_red", 0, -0.38, 1.42, 0.28, 0.08, 0.16),
            box("arm_l", "chrome", -0.31, 0, 0.78, 0.05, 0.5, 0.05),
            box("arm_r", "chrome", 0.31, 0, 0.78, 0.05, 0.5, 0.05),
            turned(box("footplate", "chrome", 0, 0.45, 0.28, 0.42, 0.2, 0.02), "0.4 0 0")]


def styling_station():
    """The counter under a mirror: a shelf top with two drawers and a few product bottles."""
    v = [box("top", "counter_white", 0, 0, 0.85, 1.0, 0.45, 0.04),
         box("cabinet", "counter_white", 0, -0.02, 0.42, 0.96, 0.4, 0.84),
         box("drawer1", "chrome", 0, 0.185, 0.6, 0.3, 0.01, 0.02),
         box("drawer2", "chrome", 0, 0.185, 0.3, 0.3, 0.01, 0.02)]
    return v + [cyl(f"bottle{k}", BOTTLES[k % 3], -0.35 + 0.12 * k, -0.1, 0.96, 0.035, 0.18)
                for k in range(3)]


def mirror():
    """A framed mirror hung on a wall: the glass looks along +y (the wall behind it at -y)."""
    return [box("frame", "black", 0, 0, 0, 0.9, 0.03, 1.1),
            box("glass", "mirror", 0, 0.016, 0, 0.82, 0.004, 1.02)]


def wash_basin():
    """A backwash basin on its pedestal, the neck rest toward +y where the client sits."""
    return [box("pedestal", "basin_black", 0, -0.05, 0.4, 0.5, 0.4, 0.8),
            cyl("bowl", "basin_black", 0, 0.05, 0.88, 0.3, 0.18),
            box("neck_rest", "rubber", 0, 0.32, 0.95, 0.16, 0.08, 0.04),
            turned(cyl("tap", "chrome", 0, -0.2, 1.05, 0.015, 0.2), "0.6 0 0"),
            cyl("spray", "chrome", 0.18, -0.18, 1.0, 0.02, 0.12)]


def hood_dryer():
    """A standing hood dryer: castored star base, a pole, the hood tilted toward +y."""
    return [cyl("base", "dark_metal", 0, 0, 0.06, 0.3, 0.04),
            cyl("pole", "chrome", 0, 0, 0.65, 0.025, 1.15),
            turned(box("arm", "chrome", 0, 0.12, 1.2, 0.04, 0.28, 0.04), "0.3 0 0"),
            turned(cyl("hood", "dryer_hood", 0, 0.25, 1.28, 0.24, 0.34), "0.6 0 0")] + castors(0.2, 0.2, 0.03)


def tool_trolley():
    """A three-tier rolling trolley of combs, clippers and sprays."""
    v = [box(f"tier{i}", "black", 0, 0, 0.15 + 0.32 * i, 0.42, 0.36, 0.03) for i in range(3)]
    v += [box(f"post{i}", "chrome", sx * 0.19, sy * 0.16, 0.45, 0.02, 0.02, 0.84)
          for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    v += [cyl(f"spray{k}", BOTTLES[k % 3], -0.12 + 0.12 * k, 0, 0.88, 0.03, 0.16) for k in range(3)]
    return v + castors(0.18, 0.15, 0.03)


def reception_desk(length=1.8, depth=0.7):
    """The front desk: a tall counter on the visitors' side (+y), a work top and a screen behind."""
    return [box("front", "desk_front", 0, depth / 2 - 0.03, 0.55, length, 0.06, 1.1),
            box("top", "counter_white", 0, depth / 2 - 0.1, 1.12, length + 0.05, 0.22, 0.04),
            box("work_top", "counter_white", 0, -0.05, 0.74, length, depth - 0.1, 0.04),
            box("side_l", "desk_front", -length / 2, 0, 0.55, 0.04, depth, 1.1),
            box("side_r", "desk_front", length / 2, 0, 0.55, 0.04, depth, 1.1),
            box("screen", "screen", 0.3, -0.1, 0.96, 0.5, 0.03, 0.32),
            box("screen_foot", "dark_metal", 0.3, -0.05, 0.77, 0.2, 0.14, 0.02)]


def product_shelf():
    """An open retail shelf of shampoos and conditioners facing +y, its back to a wall."""
    v = [box("side_l", "light_wood", -0.58, 0, 0.9, 0.04, 0.35, 1.8),
         box("side_r", "light_wood", 0.58, 0, 0.9, 0.04, 0.35, 1.8),
         box("back", "white", 0, -0.16, 0.9, 1.16, 0.02, 1.8)]
    for i in range(4):
        z = 0.3 + 0.42 * i
        v.append(box(f"shelf{i}", "light_wood", 0, 0, z, 1.12, 0.33, 0.02))
        v += [cyl(f"bottle{i}_{k}", BOTTLES[(i + k) % 3], -0.42 + 0.14 * k, 0.02, z + 0.1, 0.04, 0.18)
              for k in range(7)]
    return v


def coffee_table():
    return [box("top", "glass", 0, 0, 0.42, 1.0, 0.55, 0.03)] + legs("chrome", 0.45, 0.23, 0.41, 0.03)


def television():
    """A flat screen on a wall bracket, the picture looking along +y."""
    return [box("panel", "black", 0, 0, 0, 1.1, 0.05, 0.64),
            box("picture", "screen", 0, 0.026, 0, 1.04, 0.004, 0.58),
            box("bracket", "dark_metal", 0, -0.05, 0, 0.2, 0.06, 0.2)]


def coat_rack():
    """A standing coat rack: a heavy round foot, the pole and four hooks at the top."""
    v = [cyl("foot", "dark_metal", 0, 0, 0.02, 0.22, 0.04), cyl("pole", "wood", 0, 0, 0.9, 0.02, 1.76),
         sph("knob", "wood", 0, 0, 1.8, 0.035)]
    return v + [box(f"hook{i}", "dark_metal", 0.08 * dx, 0.08 * dy, 1.68, 0.16 if dx else 0.02,
                    0.16 if dy else 0.02, 0.02) for i, (dx, dy) in enumerate(((1, 0), (-1, 0), (0, 1), (0, -1)))]


def barber_pole():
    """The striped pole on its wall bracket: alternating red, white and blue bands under a cap."""
    v = [box("bracket", "chrome", 0, -0.09, 1.6, 0.1, 0.06, 0.9)]
    for i in range(8):
        v.append(cyl(f"band{i}", ("pole_red", "white", "pole_blue", "white")[i % 4], 0, 0, 1.2 + 0.1 * i,
                     0.07, 0.1))
    return v + [sph("cap", "chrome", 0, 0, 2.04, 0.08), cyl("base", "chrome", 0, 0, 1.13, 0.08, 0.04)]


def washing_machine():
    """A front loader, the porthole door at +y."""
    return [box("body", "white", 0, 0, 0.43, 0.6, 0.6, 0.85),
            box("panel", "grey_plastic", 0, 0.28, 0.8, 0.56, 0.05, 0.08),
            turned(cyl("door", "glass_door", 0, 0.3, 0.42, 0.18, 0.02), "1.5708 0 0"),
            turned(cyl("ring", "chrome", 0, 0.305, 0.42, 0.2, 0.01), "1.5708 0 0")]


def mini_fridge():
    return [box("body", "fridge_white", 0, 0, 0.42, 0.5, 0.55, 0.84),
            box("handle", "chrome", 0.2, 0.285, 0.55, 0.03, 0.02, 0.3),
            box("seam", "dark_metal", 0, 0.276, 0.42, 0.48, 0.002, 0.01)]


def microwave():
    return [box("body", "black", 0, 0, 0.15, 0.48, 0.36, 0.3),
            box("window", "glass_door", -0.06, 0.181, 0.15, 0.3, 0.002, 0.2),
            box("keypad", "grey_plastic", 0.17, 0.181, 0.15, 0.08, 0.002, 0.22)]


def broom():
    """A push broom leaning on the wall behind it (-y)."""
    return [turned(cyl("handle", "light_wood", 0, -0.12, 0.7, 0.014, 1.4), "0.18 0 0"),
            box("block", "wood", 0, 0, 0.06, 0.45, 0.07, 0.05),
            box("bristles", "broom_head", 0, 0, 0.02, 0.44, 0.06, 0.04)]


def walls():
    """The shop front with the entrance, the staff room partitioned off in the north-east corner."""
    return base.corner_room_walls(W, D, H, (EX0, EX1), (SX, SY), (DX0, DX1), T)


def front(out):
    """The shop front: entrance, windows, reception east of the door, waiting area in the west."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("door_1", (EX0 + 0.04, 0.47, 0, 1.5708), base.door())
    add("window_1", (1.6, T / 2 + 0.02, 1.6, 0), base.window())
    add("window_2", (9.2, T / 2 + 0.02, 1.6, 0), base.window())
    # reception: the desk facing the door (visitors on its west side), the product shelf behind it
    add("reception_desk", (6.4, 1.5, 0, 1.5708), reception_desk())
    add("product_shelf", (7.2, T / 2 + 0.19, 0, 0), product_shelf())
    add("potted_plant_1", (5.9, 0.4, 0, 0), base.plant())
    # the waiting area: the sofa on the west wall facing east, its table, the TV on the south wall
    add("sofa", (T / 2 + 0.45, 1.9, 0, -1.5708), base.sofa())
    add("coffee_table", (1.45, 1.9, 0, 1.5708), coffee_table())
    add("television", (3.0, T / 2 + 0.06, 1.7, 0), television())
    add("coat_rack", (4.05, 0.45, 0, 0), coat_rack())
    add("potted_plant_2", (0.4, 0.4, 0, 0), base.plant())


def work_area(out):
    """Styling stations on the north wall, hood dryers in the corner, wash basins on the west."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    for i, x in enumerate((2.9, 4.2, 5.5, 6.8), 1):
        add(f"styling_station_{i}", (x, D - T / 2 - 0.23, 0, 3.1416), styling_station())
        add(f"mirror_{i}", (x, D - T / 2 - 0.02, 1.55, 3.1416), mirror())
        add(f"styling_chair_{i}", (x, D - 1.1, 0, 0), styling_chair())  # facing its mirror
    add("tool_trolley_1", (3.55, D - 0.75, 0, 0), tool_trolley())
    add("tool_trolley_2", (6.15, D - 0.75, 0, 0), tool_trolley())
    add("hood_dryer_1", (0.55, 7.35, 0, 3.1416), hood_dryer())
    add("hood_dryer_2", (1.45, 7.35, 0, 3.1416), hood_dryer())
    for i, y in enumerate((3.6, 4.6, 5.6), 1):
        add(f"wash_basin_{i}", (T / 2 + 0.3, y, 0, -1.5708), wash_basin())
    # the barber's corner (south-east): two barber chairs facing mirrors on the east wall
    for i, y in enumerate((1.4, 2.9), 5):
        add(f"mirror_{i}", (W - T / 2 - 0.02, y, 1.5, 1.5708), mirror())
        add(f"barber_chair_{i - 4}", (W - 1.0, y, 0, -1.5708), barber_chair())
    add("barber_pole", (W - T / 2 - 0.12, 0.45, 0, 1.5708), barber_pole())


def staff_room(out):
    """The staff room (north-east), its door hinged at x 8.6 and swung open into the room."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("door_2", (DX0 + 0.04, SY + 0.47, 0, 1.5708), base.door())
    add("window_3", (W - T / 2 - 0.02, 6.7, 1.6, 1.5708), base.window())
    for i, x in enumerate((8.6, 9.55), 1):
        add(f"locker_{i}", (x, D - T / 2 - 0.25, 0, 3.1416), base.locker())
    add("washing_machine", (W - T / 2 - 0.32, 6.0, 0, 1.5708), washing_machine())
    add("mini_fridge", (W - T / 2 - 0.3, 7.55, 0, 1.5708), mini_fridge())
    add("microwave", (W - T / 2 - 0.3, 7.55, 0.84, 1.5708), microwave())
    add("broom", (SX + T / 2 + 0.15, 5.5, 0, -1.5708), broom())


def main():
    out = base.shell(walls(), "floor_salon", "salon_floor", W, D, H)
    front(out)
    work_area(out)
    staff_room(out)
    lights = [base.point_light(name, x, y, 2.55, "0.8 0.79 0.76")
              for name, x, y in (("light_waiting", 2.0, 1.8), ("light_reception", 6.2, 1.6),
                                 ("light_stations", 4.8, 6.4), ("light_basins", 1.4, 4.6),
                                 ("light_barber", 9.6, 2.2), ("light_staff", 9.5, 6.5))]
    print(base.world_sdf("semsplat_salon", """The semsplat salon: a hair salon of 11 m x 8 m (reception and the product shelf by the
     entrance in the south, the waiting area in the south-west, four styling stations with mirrors
     and chairs along the north wall, hood dryers, wash basins on the west wall, the barber's
     corner in the south-east, a staff room in the north-east) for measuring on a world nobody
     tuned on. Generated by salon_models/make_salon.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
