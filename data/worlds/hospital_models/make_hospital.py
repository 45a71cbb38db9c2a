#!/usr/bin/env python3
"""Writes data/worlds/hospital.world: one floor of a small hospital of 22 m x 14 m in the style of
the AWS RoboMaker hospital world (the main entrance in the south wall of the lobby in the west, the
reception desk east of it, the waiting area in the north of the lobby with two rows of waiting
chairs facing the television, the vending machine on the west wall; a corridor with handrails
running east from the lobby to the elevator door in the east wall; south of the corridor the
examination room with its couch, sink and medicine cabinet, the supply room with storage shelves,
the linen cart and waste bins, and the nurses' station, an alcove open to the corridor with the
counter, an office chair, a computer and filing cabinets; north of the corridor two patient rooms,
each with a patient bed, bedside cabinet, IV stand, patient monitor, visitor chair and a privacy
curtain; a wheelchair by the entrance, a stretcher parked in the corridor, hand-sanitizer
dispensers, fire extinguishers and potted plants) for measuring the semantic stack on a world
nobody tuned on. Every model is inline (boxes, cylinders, spheres), so the world needs no model
path. Model names are what a world author would type; the class is the name less its _<number>
("patient_bed", not "hospital_bed", as in the ward). The primitives and the SDF writing are the
office generator's, the ward's furniture is reused.
Run: python3 data/worlds/hospital_models/make_hospital.py > data/worlds/hospital.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, plant)
import make_ward as ward  # noqa: E402  (beds, curtains, IV stands, wheelchair, stretcher, sink, bins)

W, D, H = 22.0, 14.0, 2.8  # floor width (x), depth (y), wall height
T = 0.1                    # wall thickness
LX = 9.0                   # the lobby: x < LX, the whole depth
CY0, CY1 = 6.0, 8.2        # the corridor (east of the lobby) between y CY0 and CY1
EX0, EX1 = 3.6, 5.4        # the main entrance (two leaves) in the south wall of the lobby
XS1, XS2 = 14.0, 17.5      # south of the corridor: examination room | supply room | nurses' station
XN = 15.5                  # north of the corridor: patient room 1 | patient room 2
EXAM_DOOR = (10.0, 11.2)   # doorways in the corridor's south wall
SUPPLY_DOOR = (14.6, 15.5)
ROOM1_DOOR = (10.0, 11.2)  # doorways in the corridor's north wall (wide enough for a bed)
ROOM2_DOOR = (16.5, 17.7)

base.COL.update({
    "hospital_floor": "0.8 0.82 0.8", "counter_white": "0.94 0.93 0.9", "desk_front": "0.45 0.55 0.65",
    "seat_teal": "0.15 0.5 0.55", "vending_red": "0.7 0.12 0.12", "screen": "0.1 0.12 0.15",
    "elevator_steel": "0.72 0.74 0.76", "extinguisher_red": "0.8 0.08 0.06", "couch_blue": "0.3 0.5 0.7",
    "paper": "0.97 0.97 0.95", "cabinet_white": "0.92 0.94 0.95", "cross_green": "0.1 0.6 0.3",
    "linen": "0.85 0.9 0.95", "shelf_grey": "0.6 0.62 0.64", "box_brown": "0.65 0.5 0.32",
    "rail_wood": "0.7 0.55 0.35",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned, castors = ward.turned, ward.castors


# ---- the things (local frames: x right, y forward = the side a person faces, z up) ----
def reception_desk(length=2.4, depth=0.7):
    """The front desk: a tall counter on the visitors' side (+y) and the work top behind it."""
    return [box("front", "desk_front", 0, depth / 2 - 0.03, 0.55, length, 0.06, 1.1),
            box("top", "counter_white", 0, depth / 2 - 0.1, 1.12, length + 0.05, 0.22, 0.04),
            box("work_top", "counter_white", 0, -0.05, 0.74, length, depth - 0.1, 0.04),
            box("side_l", "desk_front", -length / 2, 0, 0.55, 0.04, depth, 1.1),
            box("side_r", "desk_front", length / 2, 0, 0.55, 0.04, depth, 1.1)]


def nurses_station(length=2.7):
    """The nurses' counter: a raised ledge to the corridor (+y), the working top behind it."""
    return [box("front", "counter", 0, 0.3, 0.55, length, 0.1, 1.1),
            box("ledge", "light_wood", 0, 0.3, 1.12, length + 0.1, 0.3, 0.04),
            box("worktop", "light_wood", 0, -0.05, 0.75, length, 0.6, 0.04),
            box("side_l", "counter", -length / 2, -0.05, 0.37, 0.04, 0.6, 0.75),
            box("side_r", "counter", length / 2, -0.05, 0.37, 0.04, 0.6, 0.75)]


def computer():
    """A desktop computer on a work top: the screen looks along +y at the keyboard, the tower beside."""
    return [box("screen", "black", 0, 0, 0.28, 0.55, 0.04, 0.34),
            box("picture", "screen", 0, 0.021, 0.28, 0.51, 0.002, 0.3),
            box("neck", "dark_metal", 0, -0.03, 0.08, 0.05, 0.04, 0.14),
            box("foot", "dark_metal", 0, -0.03, 0.01, 0.22, 0.16, 0.02),
            box("keyboard", "black", 0, 0.22, 0.012, 0.44, 0.14, 0.025),
            box("mouse", "grey_plastic", 0.3, 0.22, 0.015, 0.06, 0.1, 0.03),
            box("tower", "grey_plastic", 0.45, 0, 0.21, 0.18, 0.38, 0.42)]


def waiting_chair():
    """A waiting-room chair: moulded seat and back on a steel frame, arms to both sides."""
    return [box("seat", "seat_teal", 0, 0, 0.45, 0.52, 0.48, 0.06),
            turned(box("back", "seat_teal", 0, -0.23, 0.76, 0.52, 0.04, 0.46), "-0.12 0 0"),
            box("arm_l", "steel", -0.28, 0, 0.64, 0.03, 0.42, 0.03),
            box("arm_r", "steel", 0.28, 0, 0.64, 0.03, 0.42, 0.03)] + legs("steel", 0.24, 0.2, 0.42, 0.03)


def vending_machine():
    """A snack and drinks machine: the glass front at +y, the keypad and the pick-up flap."""
    return [box("body", "vending_red", 0, 0, 0.9, 0.9, 0.8, 1.8),
            box("glass", "glass", -0.1, 0.401, 1.05, 0.6, 0.004, 1.2),
            box("keypad", "grey_plastic", 0.32, 0.401, 1.1, 0.14, 0.004, 0.3),
            box("flap", "black", -0.1, 0.401, 0.25, 0.55, 0.004, 0.18)]


def television():
    """A flat screen on a wall bracket, the picture looking along +y."""
    return [box("panel", "black", 0, 0, 0, 1.2, 0.05, 0.7),
            box("picture", "screen", 0, 0.026, 0, 1.14, 0.004, 0.64),
            box("bracket", "dark_metal", 0, -0.05, 0, 0.2, 0.06, 0.2)]


def handrail(length):
    """A corridor handrail along x at 0.9 m, on brackets from the wall behind it (-y)."""
    n = max(2, int(length / 1.2) + 1)
    v = [turned(cyl("rail", "rail_wood", 0, 0, 0.9, 0.025, length), "0 1.5708 0")]
    return v + [box(f"bracket{i}", "steel", -length / 2 + 0.1 + i * (length - 0.2) / (n - 1), -0.045, 0.88,
                    0.03, 0.07, 0.03) for i in range(n)]


def examination_couch():
    """A padded examination couch, the raised back rest at +y, paper roll at the foot (-y)."""
    return [box("frame", "steel", 0, 0, 0.35, 0.6, 1.8, 0.5),
            box("pad", "couch_blue", 0, -0.2, 0.68, 0.7, 1.5, 0.12),
            turned(box("back_rest", "couch_blue", 0, 0.72, 0.85, 0.7, 0.5, 0.1), "0.6 0 0"),
            box("paper", "paper", 0, -0.2, 0.745, 0.5, 1.5, 0.005),
            turned(cyl("paper_roll", "paper", 0, -0.92, 0.7, 0.06, 0.55), "0 1.5708 0"),
            box("step", "steel", 0.48, -0.3, 0.12, 0.3, 0.4, 0.2)]


def medicine_cabinet():
    """A tall locked medicine cabinet with glass doors (+y), shelves of boxes, a green cross on top."""
    v = [box("body", "cabinet_white", 0, 0, 0.95, 0.9, 0.4, 1.9),
         box("door_glass", "glass", 0, 0.201, 1.2, 0.82, 0.004, 1.2),
         box("lower_door", "cabinet_white", 0, 0.202, 0.3, 0.82, 0.004, 0.5),
         box("lock", "steel", 0.35, 0.21, 0.6, 0.03, 0.02, 0.05),
         box("cross_v", "cross_green", 0, 0.202, 1.97, 0.06, 0.004, 0.18),
         box("cross_h", "cross_green", 0, 0.203, 1.97, 0.18, 0.004, 0.06)]
    for i in range(3):
        v += [box(f"box{i}_{k}", ("white", "cross_green", "box_brown")[(i + k) % 3], -0.28 + 0.19 * k, 0.05,
                  0.75 + 0.38 * i, 0.14, 0.18, 0.14) for k in range(4)]
    return v


def storage_shelf():
    """A steel storage rack of four shelves with boxes and supplies, facing +y, its back to a wall."""
    v = [box(f"post{i}", "shelf_grey", sx * 0.58, sy * 0.2, 1.0, 0.03, 0.03, 2.0)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    for i in range(4):
        z = 0.15 + 0.55 * i
        v.append(box(f"shelf{i}", "shelf_grey", 0, 0, z, 1.2, 0.45, 0.02))
        v += [box(f"box{i}_{k}", ("box_brown", "white", "linen")[(i + k) % 3], -0.4 + 0.4 * k, 0, z + 0.13,
                  0.32, 0.36, 0.24) for k in range(3)]
    return v


def linen_cart():
    """A rolling linen cart: a steel frame of two open shelves stacked with folded sheets, a handle."""
    v = [box(f"deck{i}", "steel", 0, 0, 0.2 + 0.45 * i, 0.9, 0.55, 0.02) for i in range(3)]
    v += [box(f"post{i}", "steel", sx * 0.44, sy * 0.26, 0.6, 0.02, 0.02, 0.9)
          for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    v += [box(f"linen{i}_{k}", "linen", -0.22 + 0.44 * k, 0, 0.28 + 0.45 * i, 0.4, 0.45, 0.14)
          for i in range(2) for k in range(2)]
    return v + [box("handle", "steel", 0, -0.32, 1.0, 0.6, 0.03, 0.03)] + castors(0.4, 0.22, 0.05)


def elevator_door():
    """Closed brushed-steel elevator doors on the wall (the lift looks along +y), the call buttons."""
    return [box("frame", "dark_metal", 0, 0, 1.07, 1.3, 0.03, 2.2),
            box("leaf_l", "elevator_steel", -0.28, 0.016, 1.05, 0.55, 0.004, 2.08),
            box("leaf_r", "elevator_steel", 0.28, 0.016, 1.05, 0.55, 0.004, 2.08),
            box("panel", "steel", 0.8, 0, 1.1, 0.12, 0.02, 0.25),
            sph("button_up", "white", 0.8, 0.012, 1.15, 0.02),
            sph("button_down", "white", 0.8, 0.012, 1.05, 0.02),
            box("indicator", "black", 0, 0.016, 2.3, 0.4, 0.004, 0.12)]


def fire_extinguisher():
    """A red extinguisher on its wall bracket (the wall behind at -y): body, head, hose and handle."""
    return [box("bracket", "dark_metal", 0, -0.08, 0.85, 0.1, 0.02, 0.3),
            cyl("body", "extinguisher_red", 0, 0, 0.8, 0.08, 0.5),
            sph("shoulder", "extinguisher_red", 0, 0, 1.05, 0.08),
            cyl("head", "black", 0, 0, 1.15, 0.025, 0.08),
            box("handle", "black", 0, 0.04, 1.19, 0.03, 0.12, 0.02),
            turned(cyl("hose", "black", 0.07, 0.03, 1.0, 0.012, 0.3), "0 0.3 0")]


def walls():
    """The outer walls with the main entrance; the lobby's east wall, open to the corridor; the
    corridor's walls with the doorways of the four rooms; the partitions between the rooms."""
    v, wall = base.wall_builder(H, T)
    # outer walls: the south with the entrance, then north, west, east
    wall(0, 0, EX0, 0); wall(EX1, 0, W, 0); wall(EX0, 0, EX1, 0, 2.2, H)
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    # the lobby's east wall, a wide opening (y CY0..CY1) into the corridor
    wall(LX, 0, LX, CY0, c="partition"); wall(LX, CY1, LX, D, c="partition")
    wall(LX, CY0, LX, CY1, 2.4, H, c="partition")
    # the corridor's south wall: examination room and supply room doorways, the nurses' station open
    (a0, a1), (b0, b1) = EXAM_DOOR, SUPPLY_DOOR
    wall(LX, CY0, a0, CY0, c="partition"); wall(a1, CY0, b0, CY0, c="partition")
    wall(b1, CY0, XS2, CY0, c="partition")
    wall(a0, CY0, a1, CY0, 2.1, H, c="partition"); wall(b0, CY0, b1, CY0, 2.1, H, c="partition")
    wall(XS2, CY0, W, CY0, 2.4, H, c="partition")  # a bulkhead over the nurses' station's opening
    wall(XS1, 0, XS1, CY0, c="partition"); wall(XS2, 0, XS2, CY0, c="partition")
    # the corridor's north wall: the doorways of the two patient rooms
    (c0, c1), (d0, d1) = ROOM1_DOOR, ROOM2_DOOR
    wall(LX, CY1, c0, CY1, c="partition"); wall(c1, CY1, d0, CY1, c="partition")
    wall(d1, CY1, W, CY1, c="partition")
    wall(c0, CY1, c1, CY1, 2.1, H, c="partition"); wall(d0, CY1, d1, CY1, 2.1, H, c="partition")
    wall(XN, CY1, XN, D, c="partition")
    return v


def lobby(out):
    """The main entrance, reception east of it, the waiting area in the north of the lobby."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("door_1", (EX0 + 0.04, 0.47, 0, 1.5708), base.door())  # two leaves swung open into the lobby
    add("door_2", (EX1 - 0.04, 0.47, 0, 1.5708), base.door())
    add("window_1", (1.4, T / 2 + 0.02, 1.6, 0), base.window())
    add("window_2", (7.0, T / 2 + 0.02, 1.6, 0), base.window())
    add("window_3", (T / 2 + 0.02, 11.0, 1.6, -1.5708), base.window())
    add("hand_sanitizer_1", (2.9, T / 2 + 0.06, 0, 0), ward.hand_sanitizer())
    add("wheelchair", (1.8, 0.85, 0, 0), ward.wheelchair())
    # reception: the desk facing the entrance (visitors on its west side), the clerk behind it
    add("reception_desk", (7.4, 3.0, 0, 1.5708), reception_desk())
    add("office_chair_1", (8.3, 3.0, 0, 1.5708), base.office_chair())
    add("computer_1", (7.47, 3.4, 0.76, -1.5708), computer())
    add("potted_plant_1", (8.4, 0.55, 0, 0), base.plant())
    # the west wall: the vending machine, a bin, a fire extinguisher
    add("vending_machine", (T / 2 + 0.42, 6.5, 0, -1.5708), vending_machine())
    add("waste_bin_1", (0.3, 7.4, 0, 0), ward.waste_bin())
    add("fire_extinguisher_1", (T / 2 + 0.1, 5.3, 0, -1.5708), fire_extinguisher())
    # the waiting area: two rows of waiting chairs facing the television on the north wall
    n = 0
    for y in (10.3, 11.6):
        for x in (1.6, 2.2, 2.8, 3.4, 4.0):
            n += 1
            add(f"waiting_chair_{n}", (x, y, 0, 0), waiting_chair())
    add("television", (2.8, D - T / 2 - 0.06, 1.8, 3.1416), television())
    add("potted_plant_2", (0.5, D - 0.5, 0, 0), base.plant())
    add("potted_plant_3", (LX - 0.5, D - 0.5, 0, 0), base.plant())


def corridor(out):
    """Handrails on both walls, a stretcher parked on the south side, the elevator at the east end."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    north, south = CY1 - T / 2 - 0.06, CY0 + T / 2 + 0.06
    for i, (x0, x1, y, yaw) in enumerate(((11.4, 15.9, north, 3.1416), (17.9, 20.9, north, 3.1416),
                                          (11.4, 14.4, south, 0), (15.7, 17.3, south, 0)), 1):
        add(f"handrail_{i}", ((x0 + x1) / 2, y, 0, yaw), handrail(x1 - x0))
    add("stretcher", (12.9, 6.6, 0, 1.5708), ward.stretcher())
    add("fire_extinguisher_2", (9.5, CY0 + T / 2 + 0.1, 0, 0), fire_extinguisher())
    add("hand_sanitizer_2", (9.6, CY1 - T / 2 - 0.06, 0, 3.1416), ward.hand_sanitizer())  # room 1's
    add("hand_sanitizer_3", (16.2, CY1 - T / 2 - 0.06, 0, 3.1416), ward.hand_sanitizer())  # room 2's
    add("elevator_door", (W - T / 2 - 0.02, 6.9, 0, 1.5708), elevator_door())
    add("potted_plant_4", (21.45, 7.7, 0, 0), base.plant())


def south_rooms(out):
    """The examination room, the supply room and the nurses' station, south of the corridor."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # the examination room (x LX..XS1), its door hinged at the doorway's west side, swung in
    add("door_3", (EXAM_DOOR[0] + 0.04, CY0 - 0.47, 0, 1.5708), base.door())
    add("examination_couch", (12.95, 3.2, 0, 0), examination_couch())
    add("office_chair_2", (11.9, 3.6, 0, -1.5708), base.office_chair())  # the doctor's, facing the couch
    add("sink", (LX + T / 2 + 0.23, 4.5, 0, -1.5708), ward.sink())
    add("hand_sanitizer_4", (LX + T / 2 + 0.06, 5.2, 0, -1.5708), ward.hand_sanitizer())
    add("waste_bin_2", (LX + 0.35, 3.4, 0, 0), ward.waste_bin())
    add("medicine_cabinet", (10.6, T / 2 + 0.21, 0, 0), medicine_cabinet())
    add("window_4", (12.4, T / 2 + 0.02, 1.6, 0), base.window())
    # the supply room (x XS1..XS2): shelves on the east and south walls, the linen cart, the bins
    add("door_4", (SUPPLY_DOOR[0] + 0.04, CY0 - 0.47, 0, 1.5708), base.door())
    for i, y in enumerate((1.0, 2.4, 3.8), 1):
        add(f"storage_shelf_{i}", (XS2 - T / 2 - 0.24, y, 0, 1.5708), storage_shelf())
    add("storage_shelf_4", (15.2, T / 2 + 0.24, 0, 0), storage_shelf())
    add("linen_cart", (15.6, 2.6, 0, 0), linen_cart())
    add("waste_bin_3", (XS1 + 0.35, 3.6, 0, 0), ward.waste_bin())
    add("waste_bin_4", (XS1 + 0.35, 4.2, 0, 0), ward.waste_bin())
    # the nurses' station (x XS2..W), open to the corridor: the counter, the nurse's chair and
    # computer behind it, filing cabinets on the south wall
    add("nurses_station", (19.6, 5.1, 0, 0), nurses_station())
    add("office_chair_3", (19.0, 4.3, 0, 0), base.office_chair())
    add("computer_2", (19.0, 5.1, 0.77, 3.1416), computer())
    add("filing_cabinet_1", (18.2, T / 2 + 0.32, 0, 0), base.filing_cabinet())
    add("filing_cabinet_2", (18.75, T / 2 + 0.32, 0, 0), base.filing_cabinet())
    add("window_5", (20.6, T / 2 + 0.02, 1.6, 0), base.window())
    add("waste_bin_5", (21.6, 0.4, 0, 0), ward.waste_bin())
    add("potted_plant_5", (21.5, 5.4, 0, 0), base.plant())


def patient_room(out, k, x0, x1, door, bed_x):
    """A single patient room (x x0..x1 north of the corridor): the bed's head to the north wall,
    the curtain between the bed and the door, the visitor's chair at the bed's far side."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    yb = D - T / 2 - 1.07
    add(f"door_{4 + k}", (door[0] + 0.04 if k == 2 else door[1] - 0.04, CY1 + 0.47, 0, 1.5708), base.door())
    add(f"patient_bed_{k}", (bed_x, yb, 0, 0), ward.patient_bed())
    add(f"bedside_cabinet_{k}", (bed_x + 0.8, D - 0.35, 0, 3.1416), ward.bedside_cabinet())
    add(f"patient_monitor_{k}", (bed_x + 1.45, D - 0.6, 0, 0), ward.patient_monitor())
    add(f"iv_stand_{k}", (bed_x - 0.8, yb - 0.6, 0, 0), ward.iv_stand())
    add(f"visitor_chair_{k}", (bed_x + 1.3, yb - 1.5, 0, 1.5708), ward.visitor_chair())
    add(f"privacy_curtain_{k}", (bed_x - 1.4, D - 1.6, 0, 0), ward.privacy_curtain(2.8))
    add(f"window_{5 + k}", (x0 + 1.6, D - T / 2 - 0.02, 1.6, 0), base.window())
    add(f"waste_bin_{5 + k}", (x0 + 0.4, D - 0.5, 0, 0), ward.waste_bin())


def main():
    out = base.shell(walls(), "floor_hospital", "hospital_floor", W, D, H)
    lobby(out)
    corridor(out)
    south_rooms(out)
    patient_room(out, 1, LX, XN, ROOM1_DOOR, 13.0)
    patient_room(out, 2, XN, W, ROOM2_DOOR, 19.5)
    out.append(base.model("window_8", (W - T / 2 - 0.02, 11.0, 1.6, 1.5708), base.window()))  # room 2's east
    lights = [base.point_light(name, x, y, 2.55, "0.78 0.78 0.76")
              for name, x, y in (("light_entrance", 4.5, 2.5), ("light_waiting", 3.0, 10.5),
                                 ("light_corridor_w", 12.0, 7.1), ("light_corridor_e", 18.5, 7.1),
                                 ("light_exam", 11.5, 3.0), ("light_supply", 15.7, 3.0),
                                 ("light_nurses", 19.7, 3.0), ("light_room_1", 12.2, 11.2),
                                 ("light_room_2", 18.7, 11.2))]
    print(base.world_sdf("semsplat_hospital", """The semsplat hospital: one floor of a small hospital of 22 m x 14 m (the lobby in the
     west with the main entrance, reception and the waiting area; a corridor with handrails east
     to the elevator; the examination room, the supply room and the nurses' station south of it;
     two patient rooms north of it) for measuring on a world nobody tuned on. Generated by
     hospital_models/make_hospital.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
