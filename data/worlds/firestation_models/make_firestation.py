#!/usr/bin/env python3
"""Writes data/worlds/firestation.world: a small one-floor fire station of 28 m x 18 m, for
measuring the semantic stack on a world nobody tuned on. x runs east, y north; the street and the
bay doors are in the south wall. There is no fire pole (one floor).

The appliance bay (engine bay), x 0..14, y 0..13, 5 m high: three big roller doors in the south
wall; two fire engines and a rescue van parked nose to the doors with walkways between them and
yellow lines on the concrete floor; two wall-mounted hose reels and the hose drying rack (the base
of the hose tower) on the west wall with two high windows above; along the north wall behind the
appliances the breathing-apparatus (BA) compressor and the BA cylinder rack between the doors of
the back rooms; a fire extinguisher on the east wall and one on the north wall, the alarm bell on
the east wall. Doors from the bay: north to the gear room, the decontamination room, the store
room and the gym; east to the watch room and to the training room.

The back rooms north of the bay (y 13..18), west to east:
  - the gear room (turnout gear): ten open gear lockers with helmets, tunics, leggings and boots
    along the north and west walls, a bench in the middle;
  - the decontamination room: two washer-extractors for kit on the north wall, the
    decontamination shower (a walk-in cubicle) on the east wall;
  - the store room: three storage shelves stocked with rolled spare hoses, boxes and spare
    equipment, two wall-mounted first aid kits at the back;
  - the gym: a treadmill, a rowing machine, a weight bench with a barbell, a dumbbell rack, a
    window.

East of the bay a corridor (x 19..20.6) runs the whole depth from the front door (the personnel
entrance, south wall, shut) north, with a fire extinguisher on its wall. West of it:
  - the watch room (x 14..19, y 0..6) at the front: the watch desk under the street window with a
    computer and the turnout printer, the radio console beside it, two office chairs, a wall map
    and the station clock on the north wall, the alarm bell on the east wall, an inner window
    looking into the bay; doors to the bay and the corridor;
  - the training room (y 6..12): four tables in two rows with eight chairs facing the whiteboard
    and the projector screen on the north wall; doors to the bay and the corridor;
  - the officer's office (y 12..18): a desk with a computer, an office chair, a visitor's chair, a
    filing cabinet, a bookshelf, a window.
East of the corridor:
  - the kitchen and mess room (x 20.6..28, y 0..8): the kitchen along the east wall (two fridges,
    a counter, the cooker, a counter with the microwave, the kitchen sink under a window, the
    dishwasher, a counter with the coffee machine), a first aid kit; the long dining table with
    eight chairs; the sofa facing the television on the north wall; a fire extinguisher, the
    station's second clock and an alarm bell; windows to the street;
  - the locker room (y 8..12.5): five steel lockers, a bench, two showers on the east wall, two
    toilets in cubicles on the north wall, two wash basins (sinks) on the west wall;
  - the dormitory (y 12.5..18): five bunk beds, three bedside lockers, a window.

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("bunk_bed_3" ->
"bunk bed", "ba_compressor" -> "ba compressor"). The primitives and the SDF writing are the
office generator's; a few fittings (toilet, wash basin, extinguisher, computer, television) are
the restaurant generator's.
Run: python3 data/worlds/firestation_models/make_firestation.py > data/worlds/firestation.world"""

import math
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "restaurant_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, sofa)
import make_restaurant as rest  # noqa: E402  (toilet, sink, fire extinguisher, computer, television)

W, D = 28.0, 18.0   # floor width (x), depth (y)
H, HB = 3.0, 5.0    # wall height of the rooms, of the appliance bay
T = 0.1             # wall thickness
XB, YB = 14.0, 13.0  # the appliance bay: x < XB, y < YB
XC0, XC1 = 19.0, 20.6  # the corridor
LINTEL = 2.1

BAY_DOORS = ((0.7, 4.5), (5.1, 8.9), (9.5, 13.3))  # x, south wall: the roller doors, 4.3 m high
ROLLER_TOP = 4.3
FRONT_DOOR = (19.3, 20.3)      # x, south wall: the corridor's street door
GEAR_DOOR = (2.2, 3.3)         # x, wall y = YB
DECON_DOOR = (5.5, 6.5)
STORE_DOOR = (8.2, 9.2)
GYM_DOOR = (11.0, 12.1)
BAY_WATCH_DOOR = (3.0, 4.1)    # y, wall x = XB
BAY_TRAIN_DOOR = (10.2, 11.3)
WATCH_DOOR = (4.4, 5.5)        # y, wall x = XC0
TRAIN_DOOR = (6.8, 7.9)
OFFICE_DOOR = (12.6, 13.7)
MESS_DOOR = (5.5, 6.6)         # y, wall x = XC1
LOCKER_DOOR = (9.0, 10.1)
DORM_DOOR = (14.0, 15.1)

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "concrete": "0.62 0.62 0.6", "line_yellow": "0.95 0.8 0.1", "vinyl": "0.55 0.6 0.62",
    "tile": "0.86 0.88 0.88", "kitchen_tile": "0.78 0.76 0.72", "plaster": "0.92 0.9 0.85",
    "block": "0.8 0.8 0.78", "partition": "0.88 0.86 0.82", "white_tile": "0.92 0.93 0.93",
    "fire_red": "0.78 0.05 0.05", "van_white": "0.94 0.94 0.92", "hi_vis": "0.85 0.9 0.1",
    "chevron_red": "0.85 0.1 0.1", "windscreen": "0.2 0.26 0.32", "tyre": "0.08 0.08 0.08",
    "hubcap": "0.75 0.76 0.78", "blue_light": "0.1 0.3 0.95", "amber": "0.95 0.6 0.05",
    "chrome": "0.82 0.83 0.85", "aluminium": "0.72 0.74 0.76", "steel": "0.78 0.79 0.8",
    "dark_steel": "0.45 0.46 0.48", "hose_red": "0.75 0.12 0.08", "hose_white": "0.92 0.9 0.85",
    "hose_yellow": "0.9 0.75 0.1", "brass": "0.8 0.65 0.3", "rubber": "0.1 0.1 0.1",
    "gauge": "0.95 0.95 0.92", "cylinder_black": "0.12 0.12 0.13", "cylinder_top": "0.85 0.85 0.85",
    "tunic": "0.55 0.48 0.3", "reflective": "0.85 0.88 0.6", "helmet_yellow": "0.92 0.85 0.2",
    "helmet_white": "0.95 0.95 0.95", "boot_black": "0.07 0.07 0.07", "locker_grey": "0.5 0.52 0.55",
    "pine": "0.78 0.62 0.4", "porcelain": "0.97 0.97 0.97", "shower_tray": "0.93 0.94 0.95",
    "curtain": "0.3 0.55 0.7", "screen": "0.05 0.06 0.08", "screen_lit": "0.25 0.45 0.6",
    "radio_grey": "0.3 0.32 0.34", "led_green": "0.1 0.8 0.3", "led_red": "0.9 0.1 0.1",
    "paper": "0.96 0.96 0.94", "map_land": "0.75 0.85 0.65", "map_water": "0.45 0.65 0.9",
    "map_road": "0.95 0.75 0.4", "bell_red": "0.8 0.1 0.08", "table_top": "0.85 0.82 0.74",
    "dining_wood": "0.55 0.38 0.24", "chair_blue": "0.2 0.3 0.55", "fridge_white": "0.94 0.94 0.93",
    "worktop": "0.3 0.28 0.26", "cabinet_white": "0.9 0.9 0.88", "hob": "0.1 0.1 0.1",
    "oven_glass": "0.2 0.22 0.25", "mattress": "0.9 0.9 0.95", "blanket_navy": "0.15 0.2 0.4",
    "pillow": "0.97 0.97 0.97", "bed_metal": "0.35 0.36 0.4", "belt_black": "0.12 0.12 0.12",
    "gym_grey": "0.35 0.35 0.37", "pad_black": "0.1 0.1 0.11", "plate_black": "0.14 0.14 0.15",
    "whiteboard": "0.97 0.97 0.96", "marker_blue": "0.1 0.2 0.7", "book_red": "0.6 0.15 0.12",
    "book_green": "0.15 0.4 0.25", "book_blue": "0.15 0.25 0.55", "book_tan": "0.75 0.65 0.45",
    "first_aid_green": "0.0 0.55 0.3", "cardboard": "0.72 0.58 0.4", "roller_slat": "0.7 0.72 0.74",
    "mirror": "0.8 0.85 0.88", "tap_red": "0.75 0.1 0.1", "exit_green": "0.05 0.6 0.25",
    "grey_bin": "0.42 0.45 0.48", "extinguisher_red": "0.8 0.08 0.06",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned, along_x, along_y = rest.turned, rest.along_x, rest.along_y


def wheel(name, x, y, r=0.5, w=0.35):
    return [along_x(cyl(name, "tyre", x, y, r, r, w)),
            along_x(cyl(name + "_hub", "hubcap", x + math.copysign(w / 2 + 0.005, x), y, r, r * 0.45, 0.01))]


# ---- the appliance bay (local frames: x right, y forward = the front, z up) ----
def fire_engine(length=8.5, width=2.5, height=3.2):
    """A red fire engine (pump ladder), the cab at the front (+y): the crew cab with windscreen and
    side windows, the body of roller-shutter lockers behind it, a ladder on the roof gantry, blue
    lights on the cab roof, a white stripe, the rear step with red and yellow chevrons, six
    wheels."""
    L, Wd = length, width
    cab0 = L / 2 - 2.3  # the cab from cab0 to the front
    v = [box("chassis", "dark_steel", 0, 0, 0.55, Wd - 0.5, L - 0.3, 0.3),
         box("body", "fire_red", 0, (cab0 - L / 2) / 2 - 0.05, 1.85, Wd, cab0 + L / 2 - 0.1, 2.5),
         box("cab", "fire_red", 0, (cab0 + L / 2) / 2, 1.75, Wd, L / 2 - cab0, 2.3),
         box("cab_roof", "fire_red", 0, (cab0 + L / 2) / 2 - 0.1, 2.95, Wd - 0.1, L / 2 - cab0 - 0.2, 0.1),
         box("windscreen", "windscreen", 0, L / 2 + 0.005, 2.2, Wd - 0.3, 0.01, 0.9),
         box("grille", "black", 0, L / 2 + 0.005, 1.2, 1.2, 0.01, 0.5),
         box("bumper", "chrome", 0, L / 2 + 0.06, 0.65, Wd, 0.12, 0.25),
         box("headlight_l", "paper", -0.9, L / 2 + 0.01, 1.05, 0.3, 0.01, 0.2),
         box("headlight_r", "paper", 0.9, L / 2 + 0.01, 1.05, 0.3, 0.01, 0.2),
         box("lightbar", "blue_light", 0, L / 2 - 0.4, 3.1, 1.6, 0.25, 0.12),
         box("stripe_l", "reflective", -Wd / 2 - 0.003, 0, 1.0, 0.005, L - 0.2, 0.12),
         box("stripe_r", "reflective", Wd / 2 + 0.003, 0, 1.0, 0.005, L - 0.2, 0.12),
         box("rear_step", "aluminium", 0, -L / 2 - 0.1, 0.6, Wd - 0.2, 0.25, 0.06),
         box("rear_chevrons", "hi_vis", 0, -L / 2 + 0.005, 1.5, Wd - 0.2, 0.01, 1.2),
         box("gantry", "aluminium", 0, -0.6, 3.15, 1.4, 5.0, 0.1)]
    for side, s in (("l", -1), ("r", 1)):
        v.append(box(f"side_window_{side}", "windscreen", s * (Wd / 2 + 0.003), L / 2 - 0.9, 2.3, 0.005, 1.2, 0.7))
        v.append(box(f"cab_door_{side}", "black", s * (Wd / 2 + 0.004), L / 2 - 1.2, 1.5, 0.005, 0.02, 1.3))
        v += [box(f"shutter_{side}{k}", "aluminium", s * (Wd / 2 + 0.004), cab0 - 0.6 - 1.2 * k, 1.95, 0.006, 1.05, 1.9)
              for k in range(5)]
    for k in range(2):  # the ladder: two rails and rungs
        v.append(box(f"ladder_rail{k}", "aluminium", -0.35 + 0.7 * k, -0.6, 3.32, 0.06, 6.5, 0.12))
    v += [box(f"rung{k}", "aluminium", 0, -3.6 + 0.5 * k, 3.32, 0.64, 0.04, 0.04) for k in range(13)]
    for x in (-Wd / 2 + 0.23, Wd / 2 - 0.23):
        for y in (L / 2 - 1.3, -L / 2 + 2.2, -L / 2 + 1.1):
            v += wheel(f"wheel_{'lr'[x > 0]}{y:.1f}".replace(".", "_").replace("-", "m"), x, y)
    return v


def rescue_van(length=6.0, width=2.1, height=2.8):
    """A white-and-red rescue van (a large panel van), the cab at the front (+y): windscreen, side
    windows, a sliding side door, the red stripe and chevrons, blue lights on the roof, four
    wheels."""
    L, Wd = length, width
    v = [box("body", "van_white", 0, -0.25, 1.65, Wd, L - 0.5, 2.3),
         box("bonnet", "van_white", 0, L / 2 - 0.4, 1.0, Wd, 0.8, 1.0),
         box("windscreen", "windscreen", 0, L / 2 - 0.5, 1.95, Wd - 0.2, 0.3, 0.8),
         box("grille", "black", 0, L / 2 + 0.005, 0.95, 1.1, 0.01, 0.35),
         box("bumper", "black", 0, L / 2 + 0.04, 0.55, Wd, 0.1, 0.2),
         box("stripe_l", "chevron_red", -Wd / 2 - 0.003, -0.2, 1.25, 0.005, L - 0.6, 0.35),
         box("stripe_r", "chevron_red", Wd / 2 + 0.003, -0.2, 1.25, 0.005, L - 0.6, 0.35),
         box("rear_chevrons", "hi_vis", 0, -L / 2 - 0.003, 1.4, Wd - 0.2, 0.005, 1.6),
         box("lightbar", "blue_light", 0, L / 2 - 1.0, 2.86, 1.4, 0.25, 0.12),
         box("side_door", "black", Wd / 2 + 0.004, 0.9, 1.5, 0.005, 0.02, 1.8)]
    for s in (-1, 1):
        v.append(box(f"side_window{s + 1}", "windscreen", s * (Wd / 2 + 0.003), L / 2 - 1.1, 2.0, 0.005, 0.8, 0.55))
    for x in (-Wd / 2 + 0.2, Wd / 2 - 0.2):
        for y in (L / 2 - 0.9, -L / 2 + 1.0):
            v += wheel(f"wheel_{'lr'[x > 0]}{'fr'[y < 0]}", x, y, 0.38, 0.25)
    return v


def roller_door(w=3.8, h=ROLLER_TOP):
    """A big roller door, shut, filling its opening (the street behind it at -y): horizontal
    aluminium slats, the bottom rail, the roll box over the opening on the inside (+y), the side
    guides, a wall-mounted control box."""
    v = [box("curtain", "roller_slat", 0, 0, h / 2, w, 0.06, h),
         box("bottom_rail", "dark_steel", 0, 0.02, 0.06, w, 0.09, 0.12),
         box("roll_box", "dark_steel", 0, 0.35, h + 0.3, w + 0.3, 0.6, 0.6),
         box("guide_l", "dark_steel", -w / 2 - 0.05, 0.08, h / 2, 0.1, 0.1, h),
         box("guide_r", "dark_steel", w / 2 + 0.05, 0.08, h / 2, 0.1, 0.1, h),
         box("controls", "hi_vis", w / 2 + 0.25, 0.1, 1.4, 0.16, 0.1, 0.24)]
    v += [box(f"slat{k}", "dark_steel", 0, 0.032, 0.3 + 0.25 * k, w, 0.004, 0.02) for k in range(int((h - 0.3) / 0.25))]
    return v


def hose_reel():
    """A wall-mounted hose reel (the wall behind at -y): the bracket, the drum with red hose wound
    on it, the nozzle hanging at the side."""
    v = [box("bracket", "dark_steel", 0, 0.02, 1.2, 0.3, 0.04, 0.5),
         box("arm", "dark_steel", 0, 0.12, 1.2, 0.06, 0.2, 0.06),
         turned(cyl("drum_back", "fire_red", 0, 0.22, 1.2, 0.33, 0.03), "1.5708 0 0"),
         turned(cyl("hose", "hose_red", 0, 0.3, 1.2, 0.28, 0.13), "1.5708 0 0"),
         turned(cyl("drum_front", "fire_red", 0, 0.38, 1.2, 0.33, 0.03), "1.5708 0 0"),
         cyl("nozzle_hose", "hose_red", 0.3, 0.3, 0.95, 0.02, 0.4),
         cyl("nozzle", "brass", 0.3, 0.3, 0.7, 0.025, 0.12)]
    return v


def hose_drying_rack(w=2.0):
    """The base of the hose tower: a tall steel frame against the wall (behind it at -y), lengths of
    wet hose hung doubled over its top bar to drain and dry, a drip trough on the floor."""
    v = [box("post_l", "steel", -w / 2, 0, 1.75, 0.08, 0.08, 3.5),
         box("post_r", "steel", w / 2, 0, 1.75, 0.08, 0.08, 3.5),
         box("top_bar", "steel", 0, 0.05, 3.45, w + 0.1, 0.12, 0.08),
         box("foot_l", "steel", -w / 2, 0, 0.03, 0.1, 0.6, 0.06),
         box("foot_r", "steel", w / 2, 0, 0.03, 0.1, 0.6, 0.06),
         box("trough", "dark_steel", 0, 0.05, 0.06, w - 0.1, 0.5, 0.12)]
    colours = ("hose_red", "hose_white", "hose_yellow", "hose_red", "hose_white", "hose_red")
    for k, c in enumerate(colours):
        x = -w / 2 + 0.25 + (w - 0.5) * k / (len(colours) - 1)
        v += [box(f"hose{k}_a", c, x - 0.05, 0.0, 2.05, 0.07, 0.025, 2.75),
              box(f"hose{k}_b", c, x + 0.05, 0.1, 2.0, 0.07, 0.025, 2.85),
              along_x(cyl(f"coupling{k}", "brass", x, 0.1, 0.58, 0.04, 0.12))]
    return v


def ba_compressor():
    """The breathing-apparatus compressor against the wall (behind at -y): a grey acoustic cabinet
    with louvres, the gauge panel and fill valves in front, two fill hoses with their cylinder
    connectors, the filter tower on top."""
    v = [box("cabinet", "locker_grey", 0, 0, 0.75, 1.1, 0.8, 1.5),
         box("panel", "black", 0, 0.405, 1.2, 0.7, 0.01, 0.4),
         box("filter", "steel", -0.35, -0.15, 1.7, 0.16, 0.16, 0.4),
         cyl("tank", "fire_red", 0.3, -0.1, 1.65, 0.1, 0.3)]
    v += [box(f"louvre{k}", "dark_steel", 0, 0.405, 0.3 + 0.08 * k, 0.9, 0.005, 0.03) for k in range(5)]
    v += [along_y(cyl(f"gauge{k}", "gauge", -0.24 + 0.16 * k, 0.415, 1.28, 0.05, 0.01)) for k in range(4)]
    v += [cyl(f"fill_hose{k}", "black", -0.2 + 0.4 * k, 0.43, 0.8, 0.012, 0.6) for k in range(2)]
    v += [box(f"fill_valve{k}", "brass", -0.2 + 0.4 * k, 0.43, 1.1, 0.05, 0.05, 0.05) for k in range(2)]
    return v


def ba_cylinder_rack(w=1.2):
    """A steel rack against the wall (behind at -y) of charged breathing-apparatus air cylinders:
    two tiers of black carbon cylinders standing in holders, their valves up, and two BA sets
    (back plates with their cylinders) hung on the top rail."""
    v = [box("post_l", "steel", -w / 2, 0, 0.9, 0.05, 0.5, 1.8),
         box("post_r", "steel", w / 2, 0, 0.9, 0.05, 0.5, 1.8),
         box("back", "steel", 0, -0.23, 0.9, w, 0.02, 1.8)]
    for t, z in enumerate((0.05, 0.85)):
        v.append(box(f"shelf{t}", "steel", 0, 0, z, w, 0.5, 0.03))
        v.append(box(f"holder{t}", "dark_steel", 0, 0.1, z + 0.35, w, 0.03, 0.04))
        v += [cyl(f"cylinder{t}_{k}", "cylinder_black", -w / 2 + 0.14 + 0.185 * k, 0, z + 0.32, 0.08, 0.6)
              for k in range(6)]
        v += [cyl(f"valve{t}_{k}", "cylinder_top", -w / 2 + 0.14 + 0.185 * k, 0, z + 0.67, 0.03, 0.1) for k in range(6)]
    for k, x in enumerate((-0.3, 0.3)):
        v += [box(f"ba_plate{k}", "black", x, 0.05, 1.7, 0.3, 0.06, 0.55),
              cyl(f"ba_cylinder{k}", "cylinder_black", x, 0.15, 1.62, 0.08, 0.55)]
    return v


# ---- the gear room, the decontamination room ----
def gear_locker():
    """An open turnout-gear locker (the wall behind at -y): a back and two sides of steel mesh, the
    top shelf with a helmet, the fire tunic and leggings hanging on hooks, the boots on the floor
    with the leggings pulled down over them, ready to step into."""
    return [box("back", "locker_grey", 0, -0.26, 1.0, 0.6, 0.02, 2.0),
            box("side_l", "locker_grey", -0.29, 0, 1.0, 0.02, 0.55, 2.0),
            box("side_r", "locker_grey", 0.29, 0, 1.0, 0.02, 0.55, 2.0),
            box("shelf", "locker_grey", 0, 0, 1.72, 0.56, 0.53, 0.02),
            box("top", "locker_grey", 0, 0, 1.99, 0.6, 0.55, 0.02),
            sph("helmet", "helmet_yellow", 0, 0, 1.82, 0.14),
            cyl("helmet_brim", "helmet_yellow", 0, 0.02, 1.76, 0.17, 0.02),
            box("visor", "windscreen", 0, 0.13, 1.8, 0.16, 0.01, 0.06),
            box("tunic", "tunic", 0, -0.12, 1.25, 0.46, 0.22, 0.75),
            box("tunic_band", "reflective", 0, -0.009, 1.0, 0.46, 0.004, 0.05),
            box("leggings", "tunic", 0, 0.08, 0.4, 0.4, 0.22, 0.5),
            box("boot_l", "boot_black", -0.1, 0.1, 0.15, 0.12, 0.28, 0.3),
            box("boot_r", "boot_black", 0.1, 0.1, 0.15, 0.12, 0.28, 0.3),
            box("gloves", "black", 0.15, -0.05, 1.76, 0.12, 0.15, 0.04)]


def bench(length=2.0, width=0.4, c="pine"):
    """A plain wooden changing bench on steel legs."""
    return [box("seat", c, 0, 0, 0.44, length, width, 0.05)] + legs("dark_steel", length / 2 - 0.1, width / 2 - 0.05, 0.42, 0.04)


def washer_extractor():
    """A commercial washer-extractor for firefighters' kit: a steel cabinet on a plinth, the big
    round door with its porthole toward the user (+y), the control panel above."""
    return [box("plinth", "dark_steel", 0, 0, 0.1, 0.8, 0.85, 0.2),
            box("cabinet", "steel", 0, 0, 0.75, 0.8, 0.85, 1.1),
            along_y(cyl("door_ring", "dark_steel", 0, 0.43, 0.7, 0.27, 0.03)),
            along_y(cyl("porthole", "oven_glass", 0, 0.45, 0.7, 0.21, 0.02)),
            box("handle", "black", 0.25, 0.46, 0.7, 0.04, 0.04, 0.14),
            box("panel", "black", 0, 0.43, 1.18, 0.6, 0.01, 0.18),
            box("display", "screen_lit", -0.15, 0.437, 1.2, 0.14, 0.004, 0.07),
            box("detergent", "white", 0.3, 0, 1.36, 0.15, 0.15, 0.12)]


def shower(c="white_tile", decon=False):
    """A walk-in shower cubicle against the wall (behind at -y): the tray, a back and two side
    panels, the shower head on its riser and the mixer; the decontamination shower has a deluge
    head, a pull handle, a drainage grate and a half-drawn curtain across its open front (+y)."""
    v = [box("tray", "shower_tray", 0, 0, 0.04, 1.0, 1.0, 0.08),
         box("back", c, 0, -0.49, 1.1, 1.0, 0.02, 2.2),
         box("side_l", c, -0.49, 0, 1.1, 0.02, 1.0, 2.2),
         box("side_r", c, 0.49, 0, 1.1, 0.02, 1.0, 2.2),
         cyl("riser", "chrome", 0, -0.44, 1.45, 0.015, 0.9),
         box("mixer", "chrome", 0, -0.46, 1.1, 0.14, 0.04, 0.1),
         cyl("drain", "dark_steel", 0, 0, 0.085, 0.05, 0.005)]
    if decon:
        v += [cyl("deluge_head", "chrome", 0, -0.2, 2.1, 0.15, 0.05),
              box("head_arm", "chrome", 0, -0.33, 2.15, 0.03, 0.26, 0.03),
              cyl("pull_rod", "hi_vis", 0.15, -0.2, 1.8, 0.01, 0.5),
              box("pull_handle", "hi_vis", 0.15, -0.2, 1.53, 0.14, 0.02, 0.03),
              box("grate", "dark_steel", 0, 0.1, 0.085, 0.6, 0.3, 0.005),
              box("rail", "chrome", 0, 0.48, 2.1, 0.96, 0.02, 0.02),
              box("curtain", "curtain", -0.25, 0.47, 1.2, 0.46, 0.02, 1.75),
              box("sign", "hi_vis", 0, -0.475, 1.9, 0.3, 0.005, 0.2)]
    else:
        v += [box("head", "chrome", 0, -0.36, 1.92, 0.12, 0.12, 0.03),
              box("screen_glass", "glass", -0.25, 0.49, 1.0, 0.5, 0.01, 1.9)]
    return v


# ---- the watch room ----
def desk(w=1.4, d=0.7, c="light_wood"):
    return [box("top", c, 0, 0, 0.73, w, d, 0.04)] + legs("dark_metal", w / 2 - 0.04, d / 2 - 0.04, 0.71)


def radio_console():
    """The station's radio console: a steel cabinet with a sloping front of radio sets, their
    displays and lamps, a handset on its cradle, a desk microphone on a gooseneck and a speaker,
    the operator's side toward +y."""
    v = [box("cabinet", "radio_grey", 0, 0, 0.4, 1.1, 0.7, 0.8),
         box("shelf", "worktop", 0, 0.05, 0.81, 1.12, 0.62, 0.03),
         turned(box("panel", "radio_grey", 0, -0.18, 1.05, 1.08, 0.3, 0.45), "-0.35 0 0"),
         box("speaker", "black", 0.42, -0.05, 0.95, 0.2, 0.14, 0.24),
         box("handset", "black", -0.42, 0.12, 0.85, 0.06, 0.22, 0.06),
         cyl("mic_stem", "dark_metal", -0.1, 0.15, 0.93, 0.008, 0.22),
         sph("mic", "black", -0.1, 0.18, 1.05, 0.025)]
    for k in range(3):
        x = -0.33 + 0.33 * k
        v += [turned(box(f"radio{k}", "black", x, -0.1, 1.07, 0.28, 0.02, 0.16), "-0.35 0 0"),
              turned(box(f"radio_display{k}", "led_green", x - 0.05, -0.088, 1.1, 0.1, 0.004, 0.04), "-0.35 0 0"),
              sph(f"lamp{k}", "led_red", x + 0.1, -0.09, 1.05, 0.012)]
    return v


def turnout_printer():
    """The turnout printer on the watch desk: a small printer that prints the call slip with the
    address when the station is turned out, a slip hanging from its mouth (toward +y)."""
    return [box("body", "grey_plastic", 0, 0, 0.08, 0.36, 0.32, 0.16),
            box("top", "black", 0, -0.04, 0.165, 0.3, 0.2, 0.01),
            box("slip", "paper", 0, 0.17, 0.1, 0.22, 0.003, 0.14),
            sph("lamp", "led_green", 0.14, 0.16, 0.13, 0.01)]


def wall_map(w=1.8, h=1.2):
    """The station's ground map on the wall (behind it at -y), centred on the model's height: land,
    a river, the roads, the station area outlined, pins in it."""
    v = [box("frame", "black", 0, 0, 0, w + 0.06, 0.02, h + 0.06),
         box("map", "map_land", 0, 0.011, 0, w, 0.004, h),
         turned(box("river", "map_water", 0, 0.014, 0.1, w * 1.05, 0.002, 0.08), "0 -0.3 0")]
    v += [box(f"road_x{k}", "map_road", 0, 0.015, -0.4 + 0.35 * k, w, 0.002, 0.03) for k in range(3)]
    v += [box(f"road_y{k}", "map_road", -0.6 + 0.5 * k, 0.015, 0, 0.03, 0.002, h) for k in range(3)]
    v += [sph(f"pin{k}", "led_red", -0.5 + 0.27 * k, 0.02, 0.3 - 0.22 * (k % 3), 0.015) for k in range(5)]
    return v


def wall_clock(r=0.18):
    """A round station clock on the wall (behind it at -y), its face toward +y, the hands at ten
    past ten."""
    return [along_y(cyl("rim", "black", 0, 0.02, 0, r, 0.04)),
            along_y(cyl("face", "white", 0, 0.041, 0, r - 0.015, 0.004)),
            turned(box("hour", "black", -0.04, 0.045, 0.02, 0.1, 0.003, 0.015), "0 -0.5 0"),
            turned(box("minute", "black", 0.05, 0.046, 0.03, 0.13, 0.003, 0.01), "0 0.5 0")]


def alarm_bell():
    """The station's alerter bell on the wall (behind it at -y), centred on the model's height: a
    red gong on its base plate, the striker under it, a red lamp beside it."""
    return [box("plate", "bell_red", 0, 0.01, 0, 0.18, 0.02, 0.26),
            along_y(cyl("gong", "bell_red", 0, 0.07, 0.02, 0.15, 0.1)),
            sph("dome", "bell_red", 0, 0.12, 0.02, 0.05),
            box("striker", "dark_steel", 0, 0.05, -0.14, 0.04, 0.06, 0.05),
            sph("beacon", "amber", 0.17, 0.05, 0.08, 0.045)]


# ---- the kitchen and mess ----
def dining_table(w=3.0, d=1.0):
    return [box("top", "dining_wood", 0, 0, 0.745, w, d, 0.04)] + legs("dark_metal", w / 2 - 0.08, d / 2 - 0.08, 0.725, 0.05)


def chair(c="chair_blue"):
    """A stacking chair: steel legs, a moulded plastic seat and back (at -y), the sitter facing +y."""
    return [box("seat", c, 0, 0, 0.46, 0.44, 0.43, 0.04),
            box("back", c, 0, -0.2, 0.72, 0.42, 0.03, 0.36)] + legs("dark_metal", 0.19, 0.18, 0.44, 0.025) + \
        [box("back_post_l", "dark_metal", -0.19, -0.2, 0.6, 0.025, 0.025, 0.3),
         box("back_post_r", "dark_metal", 0.19, -0.2, 0.6, 0.025, 0.025, 0.3)]


def kitchen_counter(w, d=0.6):
    """A kitchen base unit with a worktop against the wall (behind it at -y): the carcass, doors
    and a drawer line toward +y, the plinth."""
    v = [box("plinth", "dark_metal", 0, -0.03, 0.05, w, d - 0.06, 0.1),
         box("carcass", "cabinet_white", 0, 0, 0.5, w, d, 0.8),
         box("worktop", "worktop", 0, 0.01, 0.91, w - 0.004, d + 0.02, 0.03)]
    n = max(1, int(round(w / 0.6)))
    for k in range(n):
        x = -w / 2 + w * (k + 0.5) / n
        v += [box(f"door_seam{k}", "grey_plastic", x - w / (2 * n) + 0.003, d / 2 + 0.002, 0.45, 0.006, 0.004, 0.7),
              box(f"handle{k}", "steel", x + w / (2 * n) - 0.08, d / 2 + 0.015, 0.72, 0.02, 0.02, 0.12),
              box(f"drawer_line{k}", "grey_plastic", x, d / 2 + 0.002, 0.78, w / n - 0.02, 0.004, 0.006)]
    return v


def refrigerator():
    """A tall white fridge-freezer: the fridge door above, the freezer door below, long handles
    toward the user (+y)."""
    return [box("body", "fridge_white", 0, 0, 0.925, 0.8, 0.7, 1.85),
            box("gap", "grey_plastic", 0, 0.351, 0.72, 0.78, 0.004, 0.01),
            cyl("handle_top", "steel", 0.33, 0.38, 1.3, 0.013, 0.6),
            cyl("handle_bottom", "steel", 0.33, 0.38, 0.45, 0.013, 0.4),
            box("display", "led_green", -0.2, 0.352, 1.55, 0.1, 0.003, 0.05)]


def cooker():
    """A freestanding range cooker between the counters: the oven door with its window and handle
    toward the cook (+y), four burners on the hob, the knobs, a splashback and a kettle on the hob."""
    v = [box("body", "steel", 0, 0, 0.45, 0.9, 0.6, 0.9),
         box("hob", "hob", 0, 0, 0.905, 0.9, 0.6, 0.01),
         box("oven_door", "dark_steel", 0, 0.305, 0.42, 0.8, 0.01, 0.55),
         box("oven_window", "oven_glass", 0, 0.312, 0.44, 0.5, 0.004, 0.3),
         along_x(cyl("oven_handle", "steel", 0, 0.34, 0.73, 0.012, 0.65)),
         box("splashback", "steel", 0, -0.29, 1.15, 0.9, 0.02, 0.48),
         cyl("kettle", "chrome", -0.2, -0.12, 1.0, 0.09, 0.18)]
    v += [cyl(f"burner{k}", "black", (-0.2 if k % 2 else 0.2), (0.12 if k < 2 else -0.12), 0.915, 0.09, 0.01)
          for k in range(4)]
    v += [along_y(cyl(f"knob{k}", "black", -0.3 + 0.15 * k, 0.31, 0.82, 0.02, 0.03)) for k in range(5)]
    return v


def kitchen_sink(w=1.0, d=0.6):
    """The kitchen sink unit against the wall (behind at -y): a base cabinet, the worktop with a
    stainless bowl and drainer, the mixer tap, a bottle of washing-up liquid."""
    v = kitchen_counter(w, d)
    return v + [box("bowl", "steel", -0.15, 0.03, 0.925, 0.5, 0.42, 0.005),
                box("drainer", "dark_steel", 0.32, 0.03, 0.925, 0.3, 0.42, 0.004),
                cyl("tap", "chrome", -0.15, -0.22, 1.05, 0.018, 0.25),
                box("spout", "chrome", -0.15, -0.14, 1.17, 0.025, 0.17, 0.025),
                cyl("soap", "led_green", 0.3, -0.2, 1.0, 0.03, 0.16)]


def dishwasher():
    """An integrated dishwasher under the worktop line: the door toward +y with its handle and the
    control strip along the top."""
    return [box("body", "steel", 0, 0, 0.45, 0.6, 0.6, 0.9),
            box("door", "steel", 0, 0.302, 0.42, 0.58, 0.004, 0.76),
            box("controls", "black", 0, 0.302, 0.84, 0.58, 0.006, 0.08),
            box("handle", "dark_steel", 0, 0.32, 0.76, 0.3, 0.02, 0.02),
            box("worktop", "worktop", 0, 0.01, 0.91, 0.596, 0.62, 0.03)]


def microwave():
    """A microwave oven on the worktop: the door window toward +y, the control panel at its right."""
    return [box("body", "white", 0, 0, 0.15, 0.5, 0.38, 0.3),
            box("window", "oven_glass", -0.07, 0.191, 0.15, 0.3, 0.004, 0.2),
            box("panel", "black", 0.17, 0.191, 0.15, 0.12, 0.004, 0.24),
            box("display", "led_green", 0.17, 0.194, 0.24, 0.08, 0.002, 0.03)]


def coffee_machine():
    """A bean-to-cup coffee machine on the worktop: the bean hopper on top, the spouts over the
    drip tray and a mug, toward the user (+y)."""
    return [box("body", "black", 0, 0, 0.25, 0.32, 0.45, 0.5),
            box("hopper", "dark_metal", 0, -0.1, 0.53, 0.2, 0.2, 0.06),
            box("spouts", "chrome", 0, 0.2, 0.32, 0.1, 0.08, 0.04),
            box("drip_tray", "chrome", 0, 0.2, 0.04, 0.28, 0.12, 0.02),
            cyl("mug", "white", 0, 0.2, 0.1, 0.04, 0.1),
            box("display", "screen_lit", 0, 0.226, 0.42, 0.16, 0.002, 0.08)]


# ---- the dormitory, the locker room ----
def bunk_bed(w=0.95, length=2.0):
    """A steel bunk bed, the head at -y: four posts, two mattresses with pillows and navy blankets,
    the ladder at the foot end (+y), a guard rail on the top bunk."""
    v = [box(f"post{i}", "bed_metal", sx * (w / 2 - 0.025), sy * (length / 2 - 0.025), 0.85, 0.05, 0.05, 1.7)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    for k, z in enumerate((0.3, 1.3)):
        v += [box(f"frame{k}", "bed_metal", 0, 0, z, w, length, 0.05),
              box(f"mattress{k}", "mattress", 0, 0, z + 0.1, w - 0.06, length - 0.06, 0.15),
              box(f"blanket{k}", "blanket_navy", 0, 0.25, z + 0.18, w - 0.04, length - 0.6, 0.02),
              box(f"pillow{k}", "pillow", 0, -length / 2 + 0.25, z + 0.21, w - 0.3, 0.3, 0.08)]
    v += [box("guard_rail", "bed_metal", -w / 2 + 0.02, -0.2, 1.62, 0.03, length - 0.6, 0.04),
          box("ladder_l", "bed_metal", w / 2 - 0.35, length / 2 - 0.02, 0.95, 0.03, 0.03, 1.3),
          box("ladder_r", "bed_metal", w / 2 - 0.05, length / 2 - 0.02, 0.95, 0.03, 0.03, 1.3)]
    v += [box(f"ladder_rung{k}", "bed_metal", w / 2 - 0.2, length / 2 - 0.02, 0.55 + 0.3 * k, 0.3, 0.025, 0.025)
          for k in range(3)]
    return v


def bedside_locker():
    """A small bedside locker (cabinet): a drawer over a door toward +y, an alarm clock on top."""
    return [box("body", "cabinet_white", 0, 0, 0.38, 0.45, 0.45, 0.76),
            box("drawer_seam", "grey_plastic", 0, 0.226, 0.6, 0.43, 0.004, 0.006),
            box("knob", "steel", 0, 0.235, 0.67, 0.06, 0.02, 0.02),
            box("door_knob", "steel", 0.16, 0.235, 0.4, 0.02, 0.02, 0.08),
            box("alarm_clock", "black", 0.1, 0, 0.81, 0.12, 0.06, 0.09)]


def locker(w=0.9, d=0.45, h=1.85, doors=2):
    """A steel locker unit: tall doors toward +y with vents, handles and number plates."""
    v = [box("body", "locker_grey", 0, 0, h / 2, w, d, h)]
    for k in range(doors):
        x = -w / 2 + w * (k + 0.5) / doors
        if k:
            v.append(box(f"seam{k}", "dark_metal", x - w / (2 * doors), d / 2 + 0.002, h / 2, 0.008, 0.004, h - 0.05))
        v += [box(f"handle{k}", "chrome", x + w / (2 * doors) - 0.06, d / 2 + 0.012, 1.0, 0.02, 0.02, 0.1),
              box(f"number{k}", "white", x, d / 2 + 0.003, 1.6, 0.08, 0.002, 0.05)]
        v += [box(f"vent{k}_{j}", "dark_metal", x, d / 2 + 0.003, 1.75 - 0.04 * j, w / doors - 0.14, 0.002, 0.01)
              for j in range(3)]
    return v


# ---- the gym ----
def treadmill():
    """A treadmill: the deck with its black belt, the motor hood at the front (+y), two uprights to
    the console with its display and the handrails."""
    return [box("deck", "gym_grey", 0, -0.1, 0.12, 0.8, 1.7, 0.2),
            box("belt", "belt_black", 0, -0.15, 0.225, 0.55, 1.5, 0.01),
            box("hood", "gym_grey", 0, 0.8, 0.18, 0.8, 0.3, 0.3),
            box("upright_l", "gym_grey", -0.36, 0.8, 0.8, 0.06, 0.08, 1.0),
            box("upright_r", "gym_grey", 0.36, 0.8, 0.8, 0.06, 0.08, 1.0),
            turned(box("console", "black", 0, 0.8, 1.35, 0.7, 0.2, 0.25), "0.5 0 0"),
            box("display", "screen_lit", 0, 0.75, 1.38, 0.3, 0.01, 0.1),
            box("rail_l", "chrome", -0.36, 0.55, 1.05, 0.04, 0.5, 0.04),
            box("rail_r", "chrome", 0.36, 0.55, 1.05, 0.04, 0.5, 0.04)]


def rowing_machine(length=2.4):
    """A rowing machine (ergometer): the long rail on two feet, the sliding seat, the flywheel
    housing and the monitor at the front (+y), the foot stretchers and the handle on its chain."""
    return [box("rail", "aluminium", 0, -0.2, 0.35, 0.12, length - 0.4, 0.05),
            box("foot_back", "black", 0, -length / 2 + 0.05, 0.15, 0.55, 0.08, 0.3),
            box("foot_front", "black", 0, length / 2 - 0.35, 0.12, 0.5, 0.1, 0.24),
            box("seat", "pad_black", 0, -0.4, 0.42, 0.3, 0.3, 0.06),
            turned(cyl("flywheel", "gym_grey", 0, length / 2 - 0.2, 0.42, 0.25, 0.22), "0 1.5708 0"),
            box("footplate_l", "black", -0.12, length / 2 - 0.6, 0.35, 0.12, 0.25, 0.03),
            box("footplate_r", "black", 0.12, length / 2 - 0.6, 0.35, 0.12, 0.25, 0.03),
            cyl("monitor_arm", "black", 0, length / 2 - 0.3, 0.8, 0.015, 0.5),
            box("monitor", "screen", 0, length / 2 - 0.35, 1.08, 0.2, 0.04, 0.15),
            along_x(cyl("handle", "black", 0, length / 2 - 0.45, 0.6, 0.015, 0.5))]


def weight_bench():
    """A flat weight bench, the head at -y, with a barbell resting on the uprights above the head
    end, two weight plates on each end of the bar."""
    v = [box("pad", "pad_black", 0, 0, 0.45, 0.3, 1.2, 0.08),
         box("frame", "gym_grey", 0, 0, 0.25, 0.1, 1.1, 0.35),
         box("foot_f", "gym_grey", 0, 0.55, 0.03, 0.5, 0.06, 0.06),
         box("upright_l", "gym_grey", -0.3, -0.45, 0.55, 0.06, 0.06, 1.1),
         box("upright_r", "gym_grey", 0.3, -0.45, 0.55, 0.06, 0.06, 1.1),
         box("foot_b", "gym_grey", 0, -0.45, 0.03, 0.8, 0.3, 0.06),
         along_x(cyl("barbell", "chrome", 0, -0.42, 1.05, 0.014, 1.5))]
    v += [along_x(cyl(f"plate{k}", "plate_black", s * (0.5 + 0.05 * (k % 2)), -0.42, 1.05, 0.2, 0.04))
          for k, s in enumerate((-1, -1, 1, 1))]
    return v


def dumbbell_rack(w=1.2):
    """A two-tier dumbbell rack against the wall (behind at -y): pairs of hex dumbbells lying on
    the sloped tiers, smaller ones on top."""
    v = [box("end_l", "gym_grey", -w / 2, 0, 0.4, 0.05, 0.5, 0.8),
         box("end_r", "gym_grey", w / 2, 0, 0.4, 0.05, 0.5, 0.8),
         box("tier_low", "gym_grey", 0, 0.08, 0.4, w, 0.3, 0.03),
         box("tier_high", "gym_grey", 0, -0.12, 0.75, w, 0.25, 0.03)]
    for t, (y, z, r) in enumerate(((0.08, 0.48, 0.065), (-0.12, 0.81, 0.045))):
        for k in range(5):
            x = -w / 2 + 0.14 + (w - 0.28) * k / 4
            v += [along_y(cyl(f"bell{t}_{k}_a", "plate_black", x - 0.05, y, z, r, 0.08)),
                  along_y(cyl(f"bell{t}_{k}_b", "plate_black", x + 0.05, y, z, r, 0.08))]
    return v


# ---- the training room, the office ----
def table(w=1.4, d=0.6):
    return [box("top", "table_top", 0, 0, 0.73, w, d, 0.03)] + legs("dark_metal", w / 2 - 0.05, d / 2 - 0.05, 0.715, 0.035)


def whiteboard(w=1.6, h=1.0):
    """A whiteboard on the wall (behind at -y), centred on the model's height, a pen tray with
    markers, a drill diagram sketched on it."""
    return [box("frame", "aluminium", 0, 0, 0, w + 0.04, 0.02, h + 0.04),
            box("board", "whiteboard", 0, 0.011, 0, w, 0.004, h),
            box("tray", "aluminium", 0, 0.04, -h / 2 - 0.02, w - 0.2, 0.06, 0.02),
            box("marker", "marker_blue", 0.3, 0.04, -h / 2, 0.12, 0.02, 0.02),
            box("sketch0", "marker_blue", -0.3, 0.014, 0.2, 0.6, 0.002, 0.02),
            box("sketch1", "marker_blue", -0.1, 0.014, -0.1, 0.02, 0.002, 0.5)]


def projector_screen(w=2.0, h=1.4):
    """A pull-down projector screen on the wall (behind at -y), centred on the model's height: the
    white screen with a black border hanging from its case."""
    return [box("case", "grey_plastic", 0, 0.05, h / 2 + 0.06, w + 0.1, 0.1, 0.1),
            box("border", "black", 0, 0.05, 0, w, 0.006, h),
            box("screen", "white", 0, 0.054, 0.02, w - 0.08, 0.004, h - 0.12),
            box("bar", "black", 0, 0.055, -h / 2, w, 0.02, 0.03)]


def bookshelf(w=1.2, d=0.35, h=2.0):
    """A wooden bookshelf against the wall (behind at -y): five shelves of manuals and binders."""
    colours = ("book_red", "book_blue", "book_green", "book_tan", "book_blue", "book_red")
    v = [box("side_l", "oak", -w / 2 + 0.01, 0, h / 2, 0.02, d, h), box("side_r", "oak", w / 2 - 0.01, 0, h / 2, 0.02, d, h),
         box("back", "oak", 0, -d / 2 + 0.005, h / 2, w, 0.01, h), box("top", "oak", 0, 0, h - 0.01, w, d, 0.02)]
    for i in range(5):
        z = 0.05 + 0.39 * i
        v.append(box(f"shelf{i}", "oak", 0, 0, z, w - 0.04, d, 0.02))
        if i < 5:
            v += [box(f"book{i}_{k}", colours[(i + k) % 6], -w / 2 + 0.08 + 0.075 * k, 0, z + 0.15, 0.06, d - 0.08, 0.28)
                  for k in range(14) if (k + i) % 5]
    return v


def storage_shelf(w=1.8, d=0.5, fill=0):
    """A steel shelving unit against a wall (behind it at -y): four shelves stocked with rolled
    lengths of spare hose, cardboard boxes and spare kit."""
    v = [box(f"post{i}", "steel", sx * (w / 2 - 0.02), sy * (d / 2 - 0.02), 1.0, 0.04, 0.04, 2.0)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    for i, z in enumerate((0.1, 0.6, 1.1, 1.6)):
        v.append(box(f"shelf{i}", "steel", 0, 0, z, w, d, 0.02))
        kind = (i + fill) % 3
        if kind == 0:  # rolled hose lengths, on their sides
            v += [along_y(cyl(f"hose{i}_{k}", ("hose_red", "hose_white")[k % 2], -w / 2 + 0.22 + 0.34 * k, 0, z + 0.21, 0.2, 0.1))
                  for k in range(int((w - 0.1) / 0.34))]
        elif kind == 1:  # boxes
            v += [box(f"carton{i}_{k}", "cardboard", -w / 2 + 0.22 + 0.4 * k, 0, z + 0.14, 0.36, 0.4, 0.26)
                  for k in range(int((w - 0.1) / 0.4))]
        else:  # spare kit: branch pipes and couplings in crates
            v += [box(f"crate{i}_{k}", "grey_bin", -w / 2 + 0.3 + 0.6 * k, 0, z + 0.1, 0.5, 0.4, 0.18)
                  for k in range(int(w / 0.6))]
            v += [along_y(cyl(f"branch{i}_{k}", "brass", -w / 2 + 0.2 + 0.6 * k, 0, z + 0.24, 0.04, 0.35))
                  for k in range(int(w / 0.6))]
    return v


def first_aid_kit():
    """A green wall-mounted first aid kit (the wall behind at -y), centred on the model's height,
    with a white cross on its door."""
    return [box("case", "first_aid_green", 0, 0.07, 0, 0.4, 0.14, 0.3),
            box("cross_h", "white", 0, 0.141, 0, 0.14, 0.003, 0.045),
            box("cross_v", "white", 0, 0.141, 0, 0.045, 0.003, 0.14),
            box("handle", "white", 0, 0.145, 0.12, 0.1, 0.01, 0.015)]


# ---- the building ----
def walls():
    """The outer walls (the bay's 5 m high with the three roller-door openings, the rest 3 m with
    the front door), the bay's north and east walls with their doors, the partitions of the back
    rooms, the corridor walls, the partitions of the east rooms and the toilet cubicles."""
    v, wall = base.wall_builder(H, T)

    def with_openings(fixed, along, lo, hi, openings, c, top=LINTEL, zmax=H):
        """A wall along x (along = 'x', y = fixed) or y with the openings (lo..hi) in it."""
        cut = lo
        for a, b in openings:
            if along == "x":
                wall(cut, fixed, a, fixed, 0, zmax, c); wall(a, fixed, b, fixed, top, zmax, c)
            else:
                wall(fixed, cut, fixed, a, 0, zmax, c); wall(fixed, a, fixed, b, top, zmax, c)
            cut = b
        if along == "x": wall(cut, fixed, hi, fixed, 0, zmax, c)
        else: wall(fixed, cut, fixed, hi, 0, zmax, c)

    # outer walls
    with_openings(0, "x", 0, XB, BAY_DOORS, "block", ROLLER_TOP, HB)
    with_openings(0, "x", XB, W, (FRONT_DOOR,), "plaster")
    wall(0, D, W, D)
    wall(0, 0, 0, YB, 0, HB, "block"); wall(0, YB, 0, D)
    wall(W, 0, W, D)
    # the bay's inner walls
    with_openings(YB, "x", 0, XB, (GEAR_DOOR, DECON_DOOR, STORE_DOOR, GYM_DOOR), "block", LINTEL, HB)
    with_openings(XB, "y", 0, YB, (BAY_WATCH_DOOR, BAY_TRAIN_DOOR), "block", LINTEL, HB)
    wall(XB, YB, XB, D, c="partition")
    # the back rooms north of the bay
    for x in (4.5, 7.5, 10.0):
        wall(x, YB, x, D, c="partition")
    # the corridor
    with_openings(XC0, "y", 0, D, (WATCH_DOOR, TRAIN_DOOR, OFFICE_DOOR), "partition")
    with_openings(XC1, "y", 0, D, (MESS_DOOR, LOCKER_DOOR, DORM_DOOR), "partition")
    # west of the corridor: watch room | training room | office; east: mess | locker room | dormitory
    wall(XB, 6, XC0, 6, c="partition"); wall(XB, 12, XC0, 12, c="partition")
    wall(XC1, 8, W, 8, c="partition"); wall(XC1, 12.5, W, 12.5, c="partition")
    # the toilet cubicles on the locker room's north wall
    for x in (24.4, 25.6, 26.8):
        wall(x, 11.5, x, 12.5 - T / 2, 0, 2.0, "partition")
    return v


def floor():
    """The floor: concrete in the bay with yellow lines between the appliances, grey vinyl in the
    rooms, tiles in the kitchen and the locker room (thin overlays laid over the slab)."""
    v = base.floor_slab("floor_station", "vinyl", W, D)
    v.append(box("bay", "concrete", XB / 2, YB / 2, 0.0005, XB, YB, 0.001))
    v.append(box("kitchen_floor", "kitchen_tile", (XC1 + W) / 2, 4.0, 0.0005, W - XC1, 8.0, 0.001))
    v.append(box("locker_room_tile", "tile", (XC1 + W) / 2, 10.25, 0.0005, W - XC1, 4.5, 0.001))
    v.append(box("decon_tile", "tile", 6.0, 15.5, 0.0005, 3.0, 5.0, 0.001))
    for k, x in enumerate((4.8, 9.2)):
        v.append(box(f"bay_line{k}", "line_yellow", x, 5.5, 0.0012, 0.1, 10.0, 0.0004))
    v.append(box("bay_line_back", "line_yellow", XB / 2, 10.6, 0.0012, XB - 0.4, 0.1, 0.0004))
    return v


def ceiling():
    """The ceilings: 5 m over the bay, 3 m over the rest."""
    return [box("ceiling_bay", "white", XB / 2, YB / 2, HB + 0.01, XB, YB, 0.02),
            box("ceiling_back", "white", XB / 2, (YB + D) / 2, H + 0.01, XB, D - YB, 0.02),
            box("ceiling_east", "white", (XB + W) / 2, D / 2, H + 0.01, W - XB, D, 0.02)]


def swung(name, edge, wall_at, axis, into):
    """A door leaf swung open 90 degrees into a room, hinged at one edge of its opening: for a
    door in a wall along x (axis 'x', the wall at y = wall_at) the leaf stands along y; into is +1
    or -1 (the room's side)."""
    if axis == "x":
        return base.model(name, (edge, wall_at + into * 0.47, 0, WEST), base.door())
    return base.model(name, (wall_at + into * 0.47, edge, 0, N), base.door())


def appliance_bay(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    for i, (a, b) in enumerate(BAY_DOORS, 1):
        add(f"roller_door_{i}", ((a + b) / 2, 0, 0, N), roller_door(b - a))
    add("fire_engine_1", (2.6, 5.3, 0, S), fire_engine())
    add("fire_engine_2", (7.0, 5.3, 0, S), fire_engine())
    add("rescue_van", (11.4, 4.0, 0, S), rescue_van())
    add("hose_reel_1", (T / 2, 3.0, 0, E), hose_reel())
    add("hose_reel_2", (T / 2, 7.0, 0, E), hose_reel())
    add("hose_drying_rack", (T / 2 + 0.32, 11.3, 0, E), hose_drying_rack())
    add("window_1", (T / 2 + 0.02, 5.0, 3.6, E), base.window())
    add("window_2", (T / 2 + 0.02, 9.0, 3.6, E), base.window())
    add("ba_compressor", (4.25, YB - T / 2 - 0.4, 0, S), ba_compressor())
    add("ba_cylinder_rack", (7.35, YB - T / 2 - 0.26, 0, S), ba_cylinder_rack())
    add("fire_extinguisher_1", (XB - T / 2 - 0.1, 6.5, 0, WEST), rest.fire_extinguisher())
    add("fire_extinguisher_2", (10.4, YB - T / 2 - 0.1, 0, S), rest.fire_extinguisher())
    add("alarm_bell_1", (XB - T / 2, 8.0, 3.2, WEST), alarm_bell())


def back_rooms(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    out.append(swung("door_1", GEAR_DOOR[0] + 0.04, YB, "x", 1))
    out.append(swung("door_2", DECON_DOOR[0] + 0.04, YB, "x", 1))
    out.append(swung("door_3", STORE_DOOR[1] - 0.04, YB, "x", 1))
    out.append(swung("door_4", GYM_DOOR[0] + 0.04, YB, "x", 1))
    # the gear room: lockers along the north and west walls, the bench
    n = 0
    for x in (0.65, 1.25, 1.85, 2.45, 3.05, 3.65):
        n += 1
        add(f"gear_locker_{n}", (x, D - T / 2 - 0.28, 0, S), gear_locker())
    for y in (14.2, 14.8, 15.4, 16.0):
        n += 1
        add(f"gear_locker_{n}", (T / 2 + 0.28, y, 0, E), gear_locker())
    add("bench_1", (2.6, 15.6, 0, N), bench(2.0))
    # the decontamination room
    add("washer_extractor_1", (5.1, D - T / 2 - 0.43, 0, S), washer_extractor())
    add("washer_extractor_2", (6.0, D - T / 2 - 0.43, 0, S), washer_extractor())
    add("decontamination_shower", (7.5 - T / 2 - 0.5, 15.5, 0, WEST), shower("white_tile", decon=True))
    # the store room
    add("storage_shelf_1", (7.5 + T / 2 + 0.25, 15.5, 0, E), storage_shelf(1.8, 0.5, 0))
    add("storage_shelf_2", (10.0 - T / 2 - 0.25, 15.5, 0, WEST), storage_shelf(1.8, 0.5, 1))
    add("storage_shelf_3", (8.75, D - T / 2 - 0.25, 0, S), storage_shelf(1.6, 0.5, 2))
    add("first_aid_kit_1", (7.5 + T / 2, 16.95, 1.4, E), first_aid_kit())
    add("first_aid_kit_2", (10.0 - T / 2, 16.95, 1.4, WEST), first_aid_kit())
    # the gym
    add("treadmill", (13.4, 16.45, 0, N), treadmill())
    add("rowing_machine", (11.6, D - T / 2 - 0.45, 0, E), rowing_machine())
    add("weight_bench", (12.2, 15.0, 0, N), weight_bench())
    add("dumbbell_rack", (10.0 + T / 2 + 0.25, 15.5, 0, E), dumbbell_rack())
    add("window_3", (11.6, D - T / 2 - 0.02, 1.7, S), base.window())


def west_rooms(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # the front door (shut) and the corridor
    add("door_5", (sum(FRONT_DOOR) / 2, 0.06, 0, N), base.door())
    add("fire_extinguisher_3", (XC1 - T / 2 - 0.1, 2.0, 0, WEST), rest.fire_extinguisher())
    # the watch room
    out.append(swung("door_6", BAY_WATCH_DOOR[0] + 0.04, XB, "y", 1))
    out.append(swung("door_7", WATCH_DOOR[1] - 0.04, XC0, "y", -1))
    add("desk_1", (16.3, T / 2 + 0.45, 0, N), desk(1.8, 0.8))
    add("computer_1", (16.35, 0.45, 0.752, N), rest.computer())
    add("turnout_printer", (15.6, 0.4, 0.75, N), turnout_printer())
    add("radio_console", (18.2, T / 2 + 0.37, 0, N), radio_console())
    add("office_chair_1", (16.3, 1.45, 0, S), base.office_chair())
    add("office_chair_2", (18.2, 1.35, 0, S), base.office_chair())
    add("wall_map", (16.4, 6 - T / 2, 1.6, S), wall_map())
    add("wall_clock_1", (18.3, 6 - T / 2, 2.3, S), wall_clock())
    add("alarm_bell_2", (XC0 - T / 2, 2.2, 2.3, WEST), alarm_bell())
    add("window_4", (16.3, T / 2 + 0.02, 1.65, N), base.window())
    add("window_5", (XB + T / 2 + 0.02, 1.5, 1.5, E), base.window())  # onto the bay
    # the training room
    out.append(swung("door_8", BAY_TRAIN_DOOR[1] - 0.04, XB, "y", 1))
    out.append(swung("door_9", TRAIN_DOOR[0] + 0.04, XC0, "y", -1))
    t = c = 0
    for y in (10.0, 8.4):
        for x in (15.8, 17.4):
            t += 1
            add(f"table_{t}", (x, y, 0, N), table())
            for dx in (-0.35, 0.35):
                c += 1
                add(f"chair_{c}", (x + dx, y - 0.55, 0, N), chair())
    add("whiteboard", (15.2, 12 - T / 2, 1.4, S), whiteboard())
    add("projector_screen", (17.4, 12 - T / 2, 1.75, S), projector_screen())
    # the officer's office
    out.append(swung("door_10", OFFICE_DOOR[0] + 0.04, XC0, "y", -1))
    add("desk_2", (16.5, 16.3, 0, N), desk(1.4, 0.7, "wood"))
    add("computer_2", (16.5, 16.15, 0.752, N), rest.computer())
    add("office_chair_3", (16.5, 17.05, 0, S), base.office_chair())
    c += 1
    add(f"chair_{c}", (16.5, 15.45, 0, N), chair())
    add("filing_cabinet", (XB + T / 2 + 0.32, 17.45, 0, E), base.filing_cabinet())
    add("bookshelf", (XB + T / 2 + 0.18, 14.8, 0, E), bookshelf())
    add("window_6", (16.5, D - T / 2 - 0.02, 1.5, S), base.window())
    return c


def east_rooms(out, c):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    xe = W - T / 2  # the east wall's inner face
    # the kitchen and mess room
    out.append(swung("door_11", MESS_DOOR[1] - 0.04, XC1, "y", 1))
    add("refrigerator_1", (xe - 0.35, 0.55, 0, WEST), refrigerator())
    add("refrigerator_2", (xe - 0.35, 1.4, 0, WEST), refrigerator())
    add("kitchen_counter_1", (xe - 0.3, 2.2, 0, WEST), kitchen_counter(0.8))
    add("cooker", (xe - 0.3, 3.05, 0, WEST), cooker())
    add("kitchen_counter_2", (xe - 0.3, 4.1, 0, WEST), kitchen_counter(1.2))
    add("microwave", (xe - 0.3, 4.25, 0.925, WEST), microwave())
    add("sink_1", (xe - 0.3, 5.2, 0, WEST), kitchen_sink())
    add("dishwasher", (xe - 0.3, 6.0, 0, WEST), dishwasher())
    add("kitchen_counter_3", (xe - 0.3, 7.05, 0, WEST), kitchen_counter(1.4))
    add("coffee_machine", (xe - 0.3, 7.2, 0.925, WEST), coffee_machine())
    add("window_7", (xe - 0.02, 5.2, 1.85, WEST), base.window())
    add("first_aid_kit_3", (26.6, 8 - T / 2, 1.5, S), first_aid_kit())
    add("dining_table", (23.8, 2.9, 0, N), dining_table())
    for x in (22.8, 23.8, 24.8):
        c += 1
        add(f"chair_{c}", (x, 1.85, 0, N), chair("chair_blue"))
        c += 1
        add(f"chair_{c}", (x, 3.95, 0, S), chair("chair_blue"))
    c += 1
    add(f"chair_{c}", (21.75, 2.9, 0, E), chair("chair_blue"))
    c += 1
    add(f"chair_{c}", (25.85, 2.9, 0, WEST), chair("chair_blue"))
    add("sofa", (24.0, 5.6, 0, N), base.sofa())
    add("television", (24.0, 8 - T / 2 - 0.05, 1.6, S), rest.television())
    add("fire_extinguisher_4", (21.3, 8 - T / 2 - 0.1, 0, S), rest.fire_extinguisher())
    add("wall_clock_2", (XC1 + T / 2, 3.0, 2.25, E), wall_clock())
    add("alarm_bell_3", (XC1 + T / 2, 1.5, 2.4, E), alarm_bell())
    add("window_8", (22.5, T / 2 + 0.02, 1.5, N), base.window())
    add("window_9", (25.2, T / 2 + 0.02, 1.5, N), base.window())
    # the locker room
    out.append(swung("door_12", LOCKER_DOOR[1] - 0.04, XC1, "y", 1))
    for i, x in enumerate((21.5, 22.4, 23.3, 24.2, 25.1), 1):
        add(f"locker_{i}", (x, 8 + T / 2 + 0.23, 0, N), locker())
    add("bench_2", (23.3, 9.6, 0, N), bench(2.4, 0.4))
    add("shower_1", (xe - 0.5, 9.0, 0, WEST), shower())
    add("shower_2", (xe - 0.5, 10.1, 0, WEST), shower())
    add("toilet_1", (25.0, 12.5 - T / 2 - 0.31, 0, S), rest.toilet())
    add("toilet_2", (26.2, 12.5 - T / 2 - 0.31, 0, S), rest.toilet())
    add("sink_2", (XC1 + T / 2 + 0.01, 11.0, 0, E), rest.sink())
    add("sink_3", (XC1 + T / 2 + 0.01, 11.8, 0, E), rest.sink())
    # the dormitory
    out.append(swung("door_13", DORM_DOOR[0] + 0.04, XC1, "y", 1))
    b = 0
    for x in (22.2, 24.4, 26.6):
        b += 1
        add(f"bunk_bed_{b}", (x, D - T / 2 - 1.0, 0, S), bunk_bed())
    for x in (24.4, 26.6):
        b += 1
        add(f"bunk_bed_{b}", (x, 12.5 + T / 2 + 1.0, 0, N), bunk_bed())
    add("bedside_locker_1", (23.3, D - T / 2 - 0.25, 0, S), bedside_locker())
    add("bedside_locker_2", (25.5, D - T / 2 - 0.25, 0, S), bedside_locker())
    add("bedside_locker_3", (25.5, 12.5 + T / 2 + 0.25, 0, N), bedside_locker())
    add("window_10", (xe - 0.02, 15.25, 1.5, WEST), base.window())


def main():
    out = [base.model("walls", (0, 0, 0, 0), walls()),
           base.model("floor", (0, 0, 0, 0), floor()),
           base.model("ceiling", (0, 0, 0, 0), ceiling())]
    appliance_bay(out)
    back_rooms(out)
    c = west_rooms(out)
    east_rooms(out, c)
    warm, cool = "0.85 0.8 0.7", "0.8 0.8 0.78"
    lights = [base.point_light(name, x, y, z, rgb)
              for name, x, y, z, rgb in (
                  ("light_bay_sw", 3.5, 3.5, HB - 0.3, cool), ("light_bay_se", 10.5, 3.5, HB - 0.3, cool),
                  ("light_bay_nw", 3.5, 9.5, HB - 0.3, cool), ("light_bay_ne", 10.5, 9.5, HB - 0.3, cool),
                  ("light_gear", 2.25, 15.5, H - 0.25, cool), ("light_decon", 6.0, 15.5, H - 0.25, cool),
                  ("light_store", 8.75, 15.5, H - 0.25, cool), ("light_gym", 12.0, 15.5, H - 0.25, cool),
                  ("light_watch", 16.5, 3.0, H - 0.25, cool), ("light_training", 16.5, 9.0, H - 0.25, cool),
                  ("light_office", 16.5, 15.0, H - 0.25, warm), ("light_corridor_s", 19.8, 4.0, H - 0.25, cool),
                  ("light_corridor_n", 19.8, 13.0, H - 0.25, cool), ("light_kitchen", 26.0, 4.0, H - 0.25, cool),
                  ("light_mess", 23.0, 4.0, H - 0.25, warm), ("light_lockers", 24.3, 10.2, H - 0.25, cool),
                  ("light_dorm", 24.3, 15.2, H - 0.25, warm))]
    print(base.world_sdf("semsplat_firestation", """The semsplat fire station: a one-floor fire station of 28 m x 18 m (the
     appliance bay with two fire engines and a rescue van behind three roller doors, hose reels, the
     hose drying rack, the BA compressor and cylinder rack; north of the bay the gear room, the
     decontamination room, the store room and the gym; east of it the watch room, the training room
     and the officer's office along a corridor, and across it the kitchen and mess room, the locker
     room with showers and toilets, and the dormitory) for measuring on a world nobody tuned on.
     Generated by firestation_models/make_firestation.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
