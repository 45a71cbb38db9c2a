#!/usr/bin/env python3
"""Writes data/worlds/vetclinic.world: a small-animal veterinary practice of 18 m x 14 m on one
floor, for measuring the semantic stack on a world nobody tuned on.

South (y < 6), the street front in the south wall: the reception and waiting area in the
south-west (the entrance, a double door; the reception counter with two computers and two office
chairs behind it; waiting chairs along the west wall and under the front window; a walk-on pet
scale in front of the counter; a leaflet rack; two pet food display shelves on the east wall; a
dog's water bowl; two cat carriers, one on the floor and one on a chair; a fire extinguisher);
east of it, off a corridor (y 4.5..6), consultation rooms 1 and 2 and two toilets. Each
consultation room has a steel exam table, an exam stool, a desk with a computer and an office
chair, a sink unit with a wall cabinet over it and a pedal bin.
North (y > 6), west to east: the pharmacy (medicine shelves, the vaccine fridge, a dispensing
counter; doors to reception and to the treatment area) with the staff room behind it (kitchen
counter, fridge, table and four chairs, four lockers; its door into the treatment area); the
treatment and prep area (two treatment tables, worktop counters with the autoclave and the
microscope, wall cabinets, a sink, IV poles, oxygen cylinders, a patient monitor, an instrument
trolley, a clinical waste bin, a fire extinguisher; a wide double door from the corridor);
consultation room 3 (entered from the corridor) with the surgery (operating theatre) behind it,
entered from the treatment area (operating table, surgical lamp, anaesthesia machine, instrument
trolley, patient monitor, scrub sink, IV pole, oxygen cylinders, clinical waste bin); the kennel
ward in the east (five dog kennels along the east wall, six cat cages in two tiers on the west
wall, a washing machine for the bedding, an IV pole), entered from the corridor.

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("cat_cage_3" ->
"cat cage"). The primitives and the SDF writing are the office generator's.
Run: python3 data/worlds/vetclinic_models/make_vetclinic.py > data/worlds/vetclinic.world"""

import math
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, desk)

W, D, H = 18.0, 14.0, 3.0  # floor width (x), depth (y), wall height
T = 0.1                    # wall thickness
YC0, YC1 = 4.5, 6.0        # the corridor (x > 8) between the south rooms and the north rooms
XRW = 8.0                  # reception | consultation room 1
XC = (8.0, 11.0, 14.0, 16.0, 18.0)  # south rooms, west to east: consult 1 | consult 2 | toilet 1 | toilet 2
XP = 4.0                   # pharmacy and staff room (west) | treatment area
YP = 10.0                  # pharmacy (south) | staff room (north)
XT = 10.5                  # treatment area | consult 3 (south) and surgery (north)
YS = 9.0                   # consult 3 | surgery
XK = 14.5                  # consult 3 and surgery | kennel ward
LINTEL = 2.1

FRONT_DOOR = (2.2, 4.0)           # x, south wall (two leaves)
CONSULT_DOORS = ((9.8, 10.8), (12.8, 13.8))  # x, wall y = YC0
TOILET_DOORS = ((14.5, 15.5), (16.5, 17.5))  # x, wall y = YC0
PHARMACY_DOOR = (2.6, 3.6)        # x, wall y = YC1 (behind the reception counter)
TREATMENT_DOOR = (8.6, 10.2)      # x, wall y = YC1 (two leaves)
CONSULT3_DOOR = (12.8, 13.8)      # x, wall y = YC1
KENNEL_DOOR = (15.6, 16.6)        # x, wall y = YC1
PHARMACY_BACK_DOOR = (8.0, 9.0)   # y, wall x = XP (pharmacy | treatment)
STAFF_DOOR = (11.5, 12.5)         # y, wall x = XP (staff room | treatment)
SURGERY_DOOR = (10.5, 11.7)       # y, wall x = XT (treatment | surgery)

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "plaster": "0.93 0.93 0.9", "partition": "0.86 0.9 0.9", "white_tile": "0.92 0.94 0.94",
    "woodfloor": "0.62 0.47 0.32", "vinyl": "0.62 0.7 0.72", "tile": "0.85 0.87 0.87",
    "theatre_vinyl": "0.55 0.68 0.66", "kennel_resin": "0.5 0.55 0.58",
    "steel": "0.78 0.79 0.8", "dark_steel": "0.45 0.46 0.48", "rubber": "0.1 0.1 0.1",
    "black": "0.06 0.06 0.07", "porcelain": "0.97 0.97 0.97", "screen_lit": "0.25 0.45 0.6",
    "counter_oak": "0.66 0.5 0.33", "counter_front": "0.2 0.45 0.55", "laminate": "0.9 0.9 0.86",
    "cabinet_white": "0.95 0.95 0.93", "handle": "0.3 0.3 0.32", "seat_teal": "0.1 0.5 0.52",
    "seat_grey": "0.4 0.42 0.45", "mat_black": "0.12 0.13 0.13", "display_red": "0.85 0.1 0.1",
    "display_green": "0.1 0.8 0.35", "wave_yellow": "0.9 0.85 0.2", "paper": "0.96 0.96 0.94",
    "leaflet_blue": "0.25 0.45 0.8", "leaflet_orange": "0.95 0.55 0.15", "leaflet_green": "0.3 0.7 0.35",
    "leaflet_pink": "0.9 0.45 0.6", "food_red": "0.75 0.15 0.12", "food_purple": "0.45 0.25 0.55",
    "food_green": "0.2 0.55 0.3", "food_yellow": "0.9 0.75 0.2", "tin": "0.72 0.72 0.74",
    "water": "0.45 0.65 0.9", "carrier_grey": "0.7 0.72 0.72", "carrier_blue": "0.2 0.4 0.7",
    "carrier_pink": "0.85 0.45 0.6", "wire": "0.35 0.36 0.38", "bin_yellow": "0.95 0.8 0.1",
    "bin_lid_purple": "0.45 0.2 0.55", "label_black": "0.08 0.08 0.08", "pad_blue": "0.2 0.35 0.6",
    "drape_green": "0.2 0.5 0.45", "bag_clear": "0.85 0.9 0.92", "pump_grey": "0.55 0.57 0.6",
    "cylinder_black": "0.1 0.1 0.1", "shoulder_white": "0.96 0.96 0.96", "brass": "0.8 0.65 0.3",
    "bag_black": "0.15 0.15 0.15", "vaporiser_purple": "0.5 0.3 0.65", "tube_glass": "0.8 0.88 0.9",
    "flow_green": "0.2 0.7 0.3", "lamp_face": "0.98 0.98 0.9", "bedding_blanket": "0.55 0.35 0.25",
    "fleece_blanket": "0.35 0.55 0.75", "litter": "0.8 0.75 0.65", "tray_blue": "0.2 0.4 0.7",
    "box_white": "0.96 0.96 0.96", "box_blue": "0.3 0.5 0.8", "box_green": "0.4 0.7 0.45",
    "box_orange": "0.95 0.6 0.25", "bottle_amber": "0.6 0.35 0.1", "vial_glass": "0.8 0.88 0.92",
    "fridge_white": "0.95 0.95 0.95", "glass": "0.6 0.75 0.85", "locker_blue": "0.3 0.45 0.65",
    "table_top": "0.85 0.82 0.75", "chair_red": "0.7 0.2 0.18", "mug": "0.95 0.9 0.8",
    "kettle_white": "0.95 0.95 0.95", "extinguisher_red": "0.8 0.08 0.06", "mat_rubber": "0.15 0.15 0.15",
    "cabinet_grey": "0.7 0.72 0.74",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned, along_x, along_y, castors = base.turned, base.along_x, base.along_y, base.castors


def star_base(r=0.28, z=0.06, c="dark_steel", n=5):
    """A five-legged castor base (office chairs, stools, drip stands, monitor stands)."""
    v = [cyl("hub", c, 0, 0, z, 0.05, 0.05)]
    for i in range(n):
        a = 2 * math.pi * i / n
        x, y = 0.5 * r * math.cos(a), 0.5 * r * math.sin(a)
        v.append(turned(box(f"spoke{i}", c, x, y, z, r, 0.04, 0.03), f"0 0 {a:.4f}"))
        v.append(sph(f"castor{i}", "rubber", r * math.cos(a), r * math.sin(a), 0.03, 0.03))
    return v


# ---- reception and waiting (local frames: x right, y forward = the side a person uses, z up) ----
def reception_counter(length=3.0):
    """The reception counter: a high panelled front to the clients (+y) with a raised ledge, the
    low work surface for the receptionists behind it (-y), a paw logo on the front."""
    v = [box("plinth", "mat_black", 0, 0.25, 0.05, length, 0.1, 0.1),
         box("front", "counter_front", 0, 0.3, 0.6, length, 0.06, 1.0),
         box("ledge", "counter_oak", 0, 0.24, 1.12, length + 0.04, 0.3, 0.04),
         box("worktop", "counter_oak", 0, -0.15, 0.74, length, 0.6, 0.04),
         box("side_l", "counter_front", -length / 2 + 0.03, -0.06, 0.57, 0.06, 0.78, 1.1),
         box("side_r", "counter_front", length / 2 - 0.03, -0.06, 0.57, 0.06, 0.78, 1.1),
         box("pedestal", "cabinet_white", length / 2 - 0.3, -0.15, 0.36, 0.45, 0.55, 0.72),
         box("pedestal_seam", "handle", length / 2 - 0.3, -0.426, 0.45, 0.4, 0.004, 0.01),
         box("logo", "paper", 0, 0.334, 0.75, 0.5, 0.005, 0.3),
         sph("paw_pad", "counter_front", 0, 0.338, 0.7, 0.06)]
    v += [sph(f"paw_toe{i}", "counter_front", -0.09 + 0.06 * i, 0.337, 0.8 + (0.02 if i in (1, 2) else 0), 0.025)
          for i in range(4)]
    v += [box("card_terminal", "black", length / 2 - 0.4, 0.25, 1.17, 0.08, 0.16, 0.05),
          box("appointment_book", "leaflet_blue", -0.6, -0.15, 0.775, 0.3, 0.22, 0.03)]
    return v


def waiting_chair():
    """An upholstered waiting-room armchair on a steel frame, its back at -y."""
    v = [box("seat", "seat_teal", 0, 0, 0.45, 0.5, 0.48, 0.08),
         box("back", "seat_teal", 0, -0.22, 0.72, 0.5, 0.06, 0.48),
         box("arm_l", "steel", -0.27, 0, 0.64, 0.04, 0.46, 0.03),
         box("arm_r", "steel", 0.27, 0, 0.64, 0.04, 0.46, 0.03),
         box("arm_post_l", "steel", -0.27, 0.2, 0.53, 0.03, 0.03, 0.2),
         box("arm_post_r", "steel", 0.27, 0.2, 0.53, 0.03, 0.03, 0.2)]
    return v + legs("steel", 0.23, 0.2, 0.41, 0.03)


def pet_scale():
    """A walk-on platform scale for dogs: a low steel platform with a rubber mat, the column with
    the digital read-out at the back (-y)."""
    return [box("platform", "steel", 0, 0, 0.04, 1.0, 0.55, 0.07),
            box("mat", "mat_rubber", 0, 0.02, 0.078, 0.94, 0.47, 0.006),
            box("column", "steel", 0, -0.3, 0.5, 0.06, 0.05, 0.95),
            box("head", "cabinet_grey", 0, -0.29, 1.02, 0.26, 0.08, 0.16),
            box("readout", "display_red", 0, -0.249, 1.04, 0.16, 0.004, 0.05),
            box("buttons", "black", 0, -0.249, 0.98, 0.14, 0.004, 0.02)]


def leaflet_rack():
    """A floor-standing leaflet dispenser: a steel frame with four tiers of clear pockets full of
    pet-care leaflets, facing +y."""
    colours = ("leaflet_blue", "leaflet_orange", "leaflet_green", "leaflet_pink")
    v = [box("foot", "dark_steel", 0, 0.05, 0.015, 0.5, 0.4, 0.03),
         box("post_l", "steel", -0.24, 0, 0.75, 0.02, 0.02, 1.5),
         box("post_r", "steel", 0.24, 0, 0.75, 0.02, 0.02, 1.5),
         box("back", "steel", 0, -0.01, 0.8, 0.48, 0.01, 1.3)]
    for i in range(4):
        z = 0.45 + 0.3 * i
        v += [box(f"pocket{i}", "glass", 0, 0.06, z, 0.46, 0.01, 0.14),
              box(f"pocket_floor{i}", "glass", 0, 0.035, z - 0.07, 0.46, 0.06, 0.01)]
        v += [box(f"leaflet{i}_{k}", colours[(i + k) % 4], -0.115 + 0.23 * k, 0.035, z + 0.03, 0.2, 0.03, 0.2)
              for k in range(2)]
    return v


def pet_food_shelf(length=1.1):
    """A retail display shelf of pet food against a wall (behind it at -y): four shelves of dry food
    bags and boxes of tins, a header sign."""
    colours = ("food_red", "food_purple", "food_green", "food_yellow")
    v = [box("back", "cabinet_white", 0, -0.18, 0.9, length, 0.03, 1.8),
         box("side_l", "cabinet_white", -length / 2 + 0.015, 0, 0.9, 0.03, 0.4, 1.8),
         box("side_r", "cabinet_white", length / 2 - 0.015, 0, 0.9, 0.03, 0.4, 1.8),
         box("header", "food_green", 0, -0.1, 1.88, length, 0.2, 0.16)]
    for i, z in enumerate((0.1, 0.5, 0.9, 1.3)):
        v.append(box(f"shelf{i}", "cabinet_white", 0, 0, z, length - 0.03, 0.38, 0.02))
        if i % 2 == 0:  # bags of dry food standing up
            v += [box(f"bag{i}_{k}", colours[(i + k) % 4], -length / 2 + 0.15 + 0.2 * k, 0.0, z + 0.18, 0.17, 0.1, 0.34)
                  for k in range(int((length - 0.1) / 0.2))]
        else:  # tins of wet food
            v += [cyl(f"tin{i}_{k}", "tin", -length / 2 + 0.1 + 0.1 * k, 0.05 * (k % 2), z + 0.05, 0.04, 0.08)
                  for k in range(int((length - 0.1) / 0.1))]
    return v


def water_bowl():
    """A stainless steel dog water bowl on a rubber mat, filled."""
    return [box("mat", "mat_rubber", 0, 0, 0.003, 0.4, 0.3, 0.006),
            cyl("bowl", "steel", 0, 0, 0.04, 0.13, 0.07),
            cyl("rim", "steel", 0, 0, 0.075, 0.145, 0.008),
            cyl("water", "water", 0, 0, 0.07, 0.115, 0.004)]


def cat_carrier(top="carrier_blue"):
    """A plastic pet carrier: the grey base, the coloured top with its handle, the wire door at the
    front (+y)."""
    v = [box("base", "carrier_grey", 0, 0, 0.08, 0.32, 0.48, 0.16),
         box("top", top, 0, 0, 0.23, 0.32, 0.48, 0.14),
         box("handle", top, 0, 0, 0.33, 0.04, 0.2, 0.03),
         box("handle_post0", top, 0, -0.08, 0.31, 0.03, 0.02, 0.03),
         box("handle_post1", top, 0, 0.08, 0.31, 0.03, 0.02, 0.03),
         box("door_frame", "wire", 0, 0.242, 0.15, 0.26, 0.006, 0.22)]
    return v + [box(f"bar{i}", "wire", -0.1 + 0.04 * i, 0.246, 0.15, 0.006, 0.006, 0.2) for i in range(6)]


def computer():
    """A desktop computer: the monitor facing the user (+y) on its stand, the keyboard and the
    mouse in front, the tower beside it."""
    return [box("monitor", "black", 0, 0, 0.3, 0.56, 0.04, 0.34),
            box("display", "screen_lit", 0, 0.021, 0.3, 0.52, 0.002, 0.3),
            box("neck", "dark_steel", 0, -0.04, 0.1, 0.05, 0.04, 0.16),
            box("foot", "dark_steel", 0, -0.02, 0.01, 0.22, 0.16, 0.02),
            box("keyboard", "black", 0, 0.3, 0.012, 0.44, 0.14, 0.025),
            box("mouse", "black", 0.3, 0.3, 0.015, 0.06, 0.1, 0.03),
            box("tower", "black", 0.48, 0, 0.21, 0.18, 0.42, 0.42)]


def fire_extinguisher():
    """A red extinguisher on its wall bracket (the wall behind at -y)."""
    return [box("bracket", "dark_steel", 0, -0.08, 0.85, 0.1, 0.02, 0.3),
            cyl("body", "extinguisher_red", 0, 0, 0.8, 0.08, 0.5),
            sph("shoulder", "extinguisher_red", 0, 0, 1.05, 0.08),
            cyl("head", "black", 0, 0, 1.15, 0.025, 0.08),
            box("handle", "black", 0, 0.04, 1.19, 0.03, 0.12, 0.02),
            turned(cyl("hose", "black", 0.07, 0.03, 1.0, 0.012, 0.3), "0 0.3 0"),
            box("tag", "paper", 0, 0.081, 0.75, 0.06, 0.002, 0.09)]


# ---- the consultation rooms ----
def exam_table():
    """A veterinary examination table: a stainless steel top with a rubber mat and a raised lip on
    a lifting column and a wide base."""
    return [box("base", "dark_steel", 0, 0, 0.03, 0.8, 0.45, 0.06),
            box("column", "steel", 0, 0, 0.44, 0.3, 0.22, 0.76),
            box("top", "steel", 0, 0, 0.84, 1.15, 0.6, 0.04),
            box("lip_n", "steel", 0, 0.29, 0.87, 1.15, 0.02, 0.03),
            box("lip_s", "steel", 0, -0.29, 0.87, 1.15, 0.02, 0.03),
            box("mat", "mat_rubber", 0, 0, 0.863, 1.0, 0.5, 0.006),
            box("pedal", "black", 0.3, 0.2, 0.07, 0.12, 0.08, 0.03)]


def exam_stool():
    """A round stool for the vet on a gas column and a castor base, no back."""
    return star_base(0.26) + [cyl("column", "steel", 0, 0, 0.32, 0.025, 0.5),
                              cyl("seat", "seat_grey", 0, 0, 0.6, 0.19, 0.07),
                              cyl("foot_ring", "steel", 0, 0, 0.25, 0.18, 0.015)]


def sink():
    """A clinical sink unit against a wall (behind it at -y): a white base cabinet, the steel bowl
    and a lever mixer tap, the soap dispenser and the paper towel dispenser on the wall."""
    return [box("cabinet", "cabinet_white", 0, 0, 0.43, 0.8, 0.55, 0.86),
            box("door_seam", "handle", 0, 0.276, 0.43, 0.005, 0.004, 0.78),
            box("handle0", "handle", -0.05, 0.285, 0.7, 0.02, 0.02, 0.12),
            box("handle1", "handle", 0.05, 0.285, 0.7, 0.02, 0.02, 0.12),
            box("top", "laminate", 0, 0, 0.88, 0.82, 0.57, 0.04),
            box("bowl", "steel", 0, 0.03, 0.895, 0.46, 0.36, 0.01),
            cyl("tap", "steel", 0, -0.2, 0.98, 0.018, 0.16),
            box("spout", "steel", 0, -0.13, 1.05, 0.025, 0.16, 0.02),
            box("lever", "steel", 0, -0.22, 1.07, 0.02, 0.14, 0.015),
            box("soap", "white", -0.3, -0.24, 1.15, 0.1, 0.08, 0.18),
            box("towels", "white", 0.28, -0.23, 1.3, 0.3, 0.1, 0.35),
            box("towel_slot", "black", 0.28, -0.179, 1.15, 0.2, 0.004, 0.02)]


def wall_cabinet(w=0.8):
    """A white wall cupboard with two doors (the wall behind at -y), its bottom at the model's
    height."""
    return [box("body", "cabinet_white", 0, 0, 0.35, w, 0.35, 0.7),
            box("seam", "handle", 0, 0.176, 0.35, 0.005, 0.004, 0.66),
            box("handle0", "handle", -0.04, 0.185, 0.1, 0.02, 0.02, 0.1),
            box("handle1", "handle", 0.04, 0.185, 0.1, 0.02, 0.02, 0.1)]


def pedal_bin():
    """A stainless steel pedal bin with its lid and foot pedal (+y)."""
    return [cyl("body", "steel", 0, 0, 0.22, 0.15, 0.44),
            cyl("lid", "steel", 0, 0, 0.455, 0.155, 0.03),
            box("pedal", "black", 0, 0.17, 0.03, 0.1, 0.08, 0.02)]


def clinical_waste_bin():
    """A yellow clinical waste bin for contaminated waste: the body, the purple-rimmed lid, the foot
    pedal (+y) and the black hazard label."""
    return [box("body", "bin_yellow", 0, 0, 0.3, 0.42, 0.36, 0.6),
            box("lid", "bin_lid_purple", 0, 0, 0.62, 0.44, 0.38, 0.04),
            box("pedal", "black", 0, 0.21, 0.03, 0.14, 0.08, 0.02),
            box("label", "label_black", 0, 0.181, 0.4, 0.16, 0.004, 0.14),
            box("label_text", "bin_yellow", 0, 0.184, 0.4, 0.1, 0.002, 0.08)]


# ---- the treatment area and the surgery ----
def treatment_table(w=1.4, d=0.7):
    """A stainless steel wet treatment table: the tub with a lifting grid over it, the drain, a
    spray hose at one end, on steel legs with an undershelf."""
    v = [box("tub", "steel", 0, 0, 0.82, w, d, 0.16),
         box("grid", "dark_steel", 0, 0, 0.905, w - 0.06, d - 0.06, 0.01)]
    v += [box(f"grid_bar{i}", "steel", -w / 2 + 0.1 + 0.1 * i, 0, 0.912, 0.015, d - 0.08, 0.01)
          for i in range(int((w - 0.1) / 0.1))]
    v += [box("undershelf", "steel", 0, 0, 0.25, w - 0.08, d - 0.08, 0.02),
          cyl("riser", "steel", w / 2 - 0.06, -d / 2 + 0.05, 1.1, 0.015, 0.4),
          box("spray_arm", "steel", w / 2 - 0.06, -d / 2 + 0.12, 1.3, 0.02, 0.14, 0.02),
          cyl("spray_head", "black", w / 2 - 0.06, -d / 2 + 0.19, 1.22, 0.02, 0.12)]
    return v + legs("steel", w / 2 - 0.04, d / 2 - 0.04, 0.74)


def counter(w=3.0, d=0.6):
    """A run of base cabinets with a worktop against a wall (behind it at -y): cupboard doors and a
    bank of drawers."""
    v = [box("plinth", "mat_black", 0, 0.02, 0.05, w, d - 0.06, 0.1),
         box("carcass", "cabinet_white", 0, 0, 0.46, w, d, 0.72),
         box("worktop", "laminate", 0, 0.01, 0.86, w + 0.02, d + 0.02, 0.04)]
    n = int(w / 0.5)
    for i in range(n):
        x = -w / 2 + 0.25 + 0.5 * i
        v += [box(f"seam{i}", "handle", x + 0.25, d / 2 + 0.002, 0.46, 0.005, 0.004, 0.7),
              box(f"handle{i}", "handle", x, d / 2 + 0.012, 0.76, 0.14, 0.02, 0.02)]
    return v


def autoclave():
    """A benchtop autoclave (steriliser): the box, the round pressure door at the front (+y), the
    control panel with its display beside it."""
    return [box("body", "cabinet_grey", 0, 0, 0.2, 0.5, 0.55, 0.4),
            along_y(cyl("door", "steel", -0.06, 0.28, 0.2, 0.15, 0.03)),
            along_y(cyl("door_handle", "black", -0.06, 0.3, 0.2, 0.03, 0.04)),
            box("panel", "black", 0.19, 0.276, 0.2, 0.1, 0.004, 0.3),
            box("display", "display_green", 0.19, 0.279, 0.3, 0.07, 0.002, 0.04),
            box("feet", "rubber", 0, 0, 0.005, 0.46, 0.5, 0.01)]


def microscope():
    """A laboratory microscope on the bench: the base, the arm, the stage with a slide, the
    objectives and the head with its eyepieces toward the user (+y)."""
    return [box("base", "cabinet_white", 0, 0, 0.02, 0.2, 0.24, 0.04),
            box("arm", "cabinet_white", 0, -0.08, 0.2, 0.06, 0.06, 0.34),
            box("stage", "black", 0, 0.02, 0.15, 0.14, 0.14, 0.015),
            box("slide", "vial_glass", 0, 0.02, 0.16, 0.07, 0.025, 0.003),
            cyl("objective", "steel", 0, 0.02, 0.21, 0.015, 0.06),
            box("head", "cabinet_white", 0, -0.02, 0.32, 0.08, 0.14, 0.07),
            turned(cyl("eyepiece0", "black", -0.02, 0.06, 0.38, 0.012, 0.08), "-0.6 0 0"),
            turned(cyl("eyepiece1", "black", 0.02, 0.06, 0.38, 0.012, 0.08), "-0.6 0 0")]


def iv_pole():
    """A drip stand: the castor base, the chrome pole with hooks, a fluid bag hanging from it and an
    infusion pump clamped halfway up."""
    return star_base(0.3, 0.06, "steel") + [
        cyl("pole", "steel", 0, 0, 1.0, 0.014, 1.9),
        box("hooks", "steel", 0, 0, 1.93, 0.3, 0.015, 0.015),
        box("fluid_bag", "bag_clear", 0.12, 0, 1.75, 0.1, 0.03, 0.2),
        cyl("line", "bag_clear", 0.12, 0, 1.4, 0.004, 0.5),
        box("pump", "pump_grey", 0, 0.09, 1.1, 0.16, 0.12, 0.2),
        box("pump_display", "display_green", 0, 0.151, 1.14, 0.1, 0.002, 0.05)]


def oxygen_cylinder():
    """A medical oxygen cylinder (black with a white shoulder) standing in a floor stand, its valve
    and regulator on top."""
    return [cyl("stand", "dark_steel", 0, 0, 0.02, 0.14, 0.04),
            box("stand_hoop", "dark_steel", 0, -0.11, 0.5, 0.04, 0.02, 0.9),
            cyl("body", "cylinder_black", 0, 0, 0.64, 0.09, 1.2),
            sph("shoulder", "shoulder_white", 0, 0, 1.24, 0.09),
            cyl("valve", "brass", 0, 0, 1.36, 0.022, 0.08),
            cyl("regulator", "steel", 0, 0.03, 1.42, 0.03, 0.06),
            box("gauge", "white", 0, 0.065, 1.42, 0.05, 0.01, 0.05)]


def patient_monitor():
    """A vital-signs monitor on a roll stand: the castor base, the pole, the monitor with its screen
    of coloured traces toward the user (+y), a basket of leads."""
    v = star_base(0.28) + [cyl("pole", "steel", 0, 0, 0.6, 0.02, 1.1),
                           box("basket", "wire", 0, 0.06, 0.9, 0.2, 0.1, 0.1),
                           box("monitor", "cabinet_grey", 0, 0, 1.3, 0.34, 0.14, 0.28),
                           box("screen", "black", 0, 0.071, 1.31, 0.28, 0.002, 0.2)]
    return v + [box(f"trace{i}", c, 0, 0.073, 1.37 - 0.05 * i, 0.24, 0.001, 0.01)
                for i, c in enumerate(("display_green", "wave_yellow", "water", "display_red"))]


def instrument_trolley():
    """A stainless steel instrument trolley on castors: two shelves, a push handle at -y, a sterile
    drape on top with a tray of instruments."""
    v = [box("top", "steel", 0, 0, 0.85, 0.8, 0.5, 0.02),
         box("shelf", "steel", 0, 0, 0.3, 0.8, 0.5, 0.02),
         along_x(cyl("push_bar", "steel", 0, -0.28, 0.95, 0.012, 0.7)),
         box("drape", "drape_green", 0, 0, 0.865, 0.74, 0.46, 0.005),
         box("tray", "steel", 0.1, 0.02, 0.875, 0.4, 0.28, 0.015)]
    v += [box(f"instrument{i}", "dark_steel", -0.05 + 0.06 * i, 0.02, 0.887, 0.012, 0.2, 0.006) for i in range(6)]
    v += [box(f"post{i}", "steel", sx * 0.38, sy * 0.23, 0.46, 0.025, 0.025, 0.78)
          for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    v += [box("handle_post0", "steel", -0.35, -0.26, 0.9, 0.02, 0.04, 0.1),
          box("handle_post1", "steel", 0.35, -0.26, 0.9, 0.02, 0.04, 0.1)]
    return v + castors(0.36, 0.21, 0.035)


def operating_table():
    """A veterinary operating table: the heated, padded V-top with side rails for the ties, on a
    lifting column and a heavy base."""
    return [box("base", "dark_steel", 0, 0, 0.04, 0.9, 0.5, 0.08),
            box("column", "steel", 0, 0, 0.45, 0.25, 0.25, 0.75),
            box("frame", "steel", 0, 0, 0.85, 1.35, 0.55, 0.06),
            turned(box("top_l", "pad_blue", 0, -0.13, 0.9, 1.3, 0.27, 0.04), "-0.15 0 0"),
            turned(box("top_r", "pad_blue", 0, 0.13, 0.9, 1.3, 0.27, 0.04), "0.15 0 0"),
            along_x(cyl("rail_n", "steel", 0, 0.3, 0.88, 0.01, 1.35)),
            along_x(cyl("rail_s", "steel", 0, -0.3, 0.88, 0.01, 1.35)),
            box("pedal", "black", 0.35, 0.3, 0.08, 0.15, 0.1, 0.03)]


def surgical_lamp(h=H):
    """The operating light hung from the ceiling over the table: the ceiling plate, the drop tube,
    the arm and the round lamp head with its bright face and a sterile handle."""
    return [cyl("ceiling_plate", "cabinet_white", 0, 0, h - 0.02, 0.15, 0.04),
            cyl("drop_tube", "cabinet_white", 0, 0, h - 0.3, 0.03, 0.52),
            box("arm", "cabinet_white", 0.2, 0, h - 0.56, 0.5, 0.06, 0.06),
            cyl("yoke", "cabinet_white", 0.42, 0, h - 0.68, 0.025, 0.2),
            cyl("head", "cabinet_white", 0.42, 0, h - 0.84, 0.33, 0.12),
            cyl("face", "lamp_face", 0.42, 0, h - 0.905, 0.29, 0.01),
            cyl("handle", "steel", 0.42, 0, h - 0.96, 0.02, 0.1)]


def anaesthesia_machine():
    """An anaesthetic machine on a wheeled cart: the cabinet with drawers, the worktop, the upright
    with the flowmeter tubes and the vaporiser (toward the user, +y), the rebreathing bag, the
    small monitor on the top shelf and two gas cylinders at the back."""
    v = [box("cabinet", "cabinet_grey", 0, 0, 0.45, 0.6, 0.5, 0.7),
         box("worktop", "steel", 0, 0.02, 0.82, 0.64, 0.56, 0.04),
         box("upright", "cabinet_grey", 0, -0.18, 1.15, 0.56, 0.14, 0.62),
         box("shelf", "steel", 0, -0.05, 1.47, 0.6, 0.4, 0.03),
         box("monitor", "black", 0, -0.05, 1.62, 0.3, 0.08, 0.24),
         box("monitor_screen", "display_green", 0, -0.009, 1.62, 0.24, 0.002, 0.16),
         box("vaporiser", "vaporiser_purple", 0.15, -0.05, 1.02, 0.12, 0.12, 0.22),
         box("bellows", "tube_glass", -0.15, 0.0, 0.98, 0.14, 0.14, 0.26),
         sph("rebreathing_bag", "bag_black", -0.36, 0.12, 0.95, 0.08),
         turned(cyl("hose", "bag_clear", -0.3, 0.22, 0.88, 0.015, 0.3), "1.2 0 0")]
    v += [cyl(f"flow_tube{i}", "tube_glass", -0.1 + 0.06 * i, -0.105, 1.3, 0.012, 0.2) for i in range(3)]
    v += [sph(f"float{i}", "flow_green", -0.1 + 0.06 * i, -0.1, 1.25 + 0.04 * i, 0.01) for i in range(3)]
    v += [box(f"drawer{i}", "handle", 0, 0.252, 0.25 + 0.22 * i, 0.3, 0.004, 0.02) for i in range(3)]
    v += [cyl(f"gas_cylinder{i}", "shoulder_white", -0.15 + 0.3 * i, -0.3, 0.6, 0.05, 0.6) for i in range(2)]
    return v + castors(0.26, 0.21, 0.04)


def scrub_sink(w=1.2, d=0.6):
    """A stainless surgical scrub trough against the wall (behind it at -y) on short legs: the deep
    trough, two tall gooseneck taps with elbow levers, a backsplash, the soap and brush dispensers."""
    v = [box("trough", "steel", 0, 0, 0.8, w, d, 0.3),
         box("basin", "dark_steel", 0, 0.03, 0.952, w - 0.1, d - 0.12, 0.005),
         box("backsplash", "steel", 0, -d / 2 + 0.02, 1.2, w, 0.04, 0.5),
         box("apron", "steel", 0, 0, 0.45, w, d, 0.4)]
    for i, x in enumerate((-w / 4, w / 4)):
        v += [cyl(f"tap{i}", "steel", x, -d / 2 + 0.08, 1.25, 0.015, 0.5),
              box(f"gooseneck{i}", "steel", x, -d / 2 + 0.16, 1.5, 0.02, 0.18, 0.02),
              box(f"elbow_lever{i}", "steel", x + 0.1, -d / 2 + 0.1, 1.12, 0.2, 0.02, 0.02),
              box(f"dispenser{i}", "white", x + 0.3, -d / 2 + 0.06, 1.35, 0.1, 0.08, 0.2)]
    return v + legs("steel", w / 2 - 0.04, d / 2 - 0.04, 0.25)


# ---- the kennel ward ----
def dog_kennel(w=1.3, d=1.1, h=1.4):
    """A stainless steel dog kennel: back, sides and roof panels, the barred front door (+y) with
    its latch, a dog bed with a blanket and a water bowl inside."""
    v = [box("floor_pan", "steel", 0, 0, 0.03, w, d, 0.06),
         box("back", "steel", 0, -d / 2 + 0.015, h / 2, w, 0.03, h),
         box("side_l", "steel", -w / 2 + 0.015, 0, h / 2, 0.03, d, h),
         box("side_r", "steel", w / 2 - 0.015, 0, h / 2, 0.03, d, h),
         box("roof", "steel", 0, 0, h - 0.015, w, d, 0.03),
         box("door_rail_top", "steel", 0, d / 2 - 0.02, h - 0.06, w - 0.06, 0.03, 0.04),
         box("door_rail_bottom", "steel", 0, d / 2 - 0.02, 0.1, w - 0.06, 0.03, 0.04),
         box("latch", "black", w / 2 - 0.12, d / 2 + 0.01, h / 2, 0.05, 0.03, 0.12),
         box("card_holder", "paper", -w / 2 + 0.2, d / 2 + 0.005, h - 0.2, 0.18, 0.004, 0.12),
         box("bed", "bedding_blanket", -0.15, -0.15, 0.12, 0.75, 0.6, 0.12),
         box("blanket", "fleece_blanket", -0.1, -0.15, 0.19, 0.5, 0.45, 0.02),
         cyl("bowl", "steel", w / 2 - 0.2, 0.25, 0.09, 0.09, 0.06)]
    n = int((w - 0.1) / 0.08)
    v += [cyl(f"bar{i}", "steel", -w / 2 + 0.07 + 0.08 * i, d / 2 - 0.02, h / 2, 0.008, h - 0.12) for i in range(n)]
    return v


def cat_cage(w=0.75, d=0.6, h=0.6, feet=False):
    """One stainless steel cat cage of a bank: the box, the barred front door (+y), a litter tray,
    a fleece blanket and a food bowl inside; the bottom tier stands on feet."""
    z0 = 0.1 if feet else 0.0
    v = [box("bottom", "steel", 0, 0, z0 + 0.01, w, d, 0.02),
         box("back", "steel", 0, -d / 2 + 0.01, z0 + h / 2, w, 0.02, h),
         box("side_l", "steel", -w / 2 + 0.01, 0, z0 + h / 2, 0.02, d, h),
         box("side_r", "steel", w / 2 - 0.01, 0, z0 + h / 2, 0.02, d, h),
         box("top", "steel", 0, 0, z0 + h - 0.01, w, d, 0.02),
         box("door_frame", "steel", 0, d / 2 - 0.01, z0 + 0.03, w - 0.04, 0.02, 0.03),
         box("latch", "black", w / 2 - 0.07, d / 2 + 0.005, z0 + h / 2, 0.03, 0.02, 0.08),
         box("litter_tray", "tray_blue", -w / 2 + 0.18, -0.05, z0 + 0.05, 0.3, 0.38, 0.06),
         box("litter", "litter", -w / 2 + 0.18, -0.05, z0 + 0.08, 0.27, 0.35, 0.005),
         box("blanket", "fleece_blanket", 0.17, -0.05, z0 + 0.03, 0.3, 0.4, 0.02),
         cyl("bowl", "steel", 0.2, 0.18, z0 + 0.045, 0.05, 0.03)]
    v += [cyl(f"bar{i}", "steel", -w / 2 + 0.06 + 0.06 * i, d / 2 - 0.01, z0 + h / 2, 0.005, h - 0.04)
          for i in range(int((w - 0.08) / 0.06))]
    if feet:
        v += [box(f"foot{i}", "dark_steel", sx * (w / 2 - 0.04), sy * (d / 2 - 0.04), 0.05, 0.04, 0.04, 0.1)
              for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    return v


def washing_machine():
    """A front-loading washing machine for the kennel bedding: the white cabinet, the round door
    with its window at the front (+y), the detergent drawer and the programme dial."""
    return [box("cabinet", "fridge_white", 0, 0, 0.43, 0.6, 0.6, 0.86),
            along_y(cyl("door_ring", "cabinet_grey", 0, 0.305, 0.42, 0.2, 0.02)),
            along_y(cyl("door_window", "glass", 0, 0.315, 0.42, 0.15, 0.01)),
            box("drawer", "cabinet_white", -0.18, 0.302, 0.78, 0.18, 0.004, 0.08),
            along_y(cyl("dial", "cabinet_grey", 0.15, 0.305, 0.78, 0.035, 0.02)),
            box("display", "black", 0.02, 0.302, 0.78, 0.1, 0.004, 0.04)]


# ---- the pharmacy ----
def medicine_shelf(length=1.1, fill=0):
    """White steel shelving of medicines against a wall (behind it at -y): five shelves of
    medicine boxes and brown bottles."""
    colours = ("box_white", "box_blue", "box_green", "box_orange", "box_white")
    v = [box("back", "cabinet_white", 0, -0.185, 0.95, length, 0.02, 1.9),
         box("side_l", "cabinet_white", -length / 2 + 0.015, 0, 0.95, 0.03, 0.39, 1.9),
         box("side_r", "cabinet_white", length / 2 - 0.015, 0, 0.95, 0.03, 0.39, 1.9)]
    for i, z in enumerate((0.1, 0.48, 0.86, 1.24, 1.62)):
        v.append(box(f"shelf{i}", "cabinet_white", 0, 0, z, length - 0.03, 0.37, 0.02))
        if (i + fill) % 3 == 2:  # bottles
            v += [cyl(f"bottle{i}_{k}", "bottle_amber", -length / 2 + 0.09 + 0.08 * k, 0.04 * (k % 2), z + 0.07, 0.03, 0.12)
                  for k in range(int((length - 0.1) / 0.08))]
        else:  # medicine boxes
            v += [box(f"carton{i}_{k}", colours[(i + k + fill) % 5], -length / 2 + 0.1 + 0.12 * k, 0.02, z + 0.07,
                      0.1, 0.2, 0.12) for k in range(int((length - 0.1) / 0.12))]
    return v


def vaccine_fridge():
    """A glass-door pharmacy fridge for vaccines: the white cabinet, the glass door (+y) showing
    shelves of vials, the handle, the lock and the temperature display."""
    v = [box("cabinet", "fridge_white", 0, 0, 0.8, 0.6, 0.62, 1.6),
         box("door_frame", "cabinet_grey", 0, 0.315, 0.75, 0.56, 0.01, 1.4),
         box("door_glass", "glass", 0, 0.322, 0.75, 0.48, 0.004, 1.3),
         cyl("handle", "steel", 0.25, 0.345, 0.8, 0.012, 0.5),
         box("lock", "black", 0.25, 0.325, 0.45, 0.03, 0.01, 0.03),
         box("display", "display_red", 0, 0.312, 1.53, 0.12, 0.004, 0.05)]
    for i in range(4):
        z = 0.3 + 0.3 * i
        v.append(box(f"shelf{i}", "wire", 0, 0.02, z, 0.5, 0.5, 0.01))
        v += [cyl(f"vial{i}_{k}", "vial_glass", -0.2 + 0.08 * k, 0.15, z + 0.04, 0.015, 0.07) for k in range(6)]
        v += [box(f"vaccine_box{i}", "box_blue", 0.1, -0.08, z + 0.05, 0.25, 0.2, 0.09)]
    return v


# ---- the staff room ----
def kitchen_counter(w=2.2, d=0.6):
    """A staff kitchenette against a wall (behind it at -y): base units, the worktop with an inset
    sink and tap, an electric kettle and two mugs."""
    v = counter(w, d) + [box("sink_bowl", "steel", -0.45, 0.03, 0.885, 0.45, 0.38, 0.01),
                         cyl("sink_tap", "steel", -0.45, -0.22, 0.96, 0.015, 0.16),
                         box("sink_spout", "steel", -0.45, -0.15, 1.03, 0.02, 0.14, 0.02),
                         cyl("kettle", "kettle_white", 0.5, -0.1, 0.99, 0.08, 0.22),
                         box("kettle_handle", "black", 0.5, -0.19, 1.0, 0.02, 0.04, 0.15),
                         cyl("mug0", "mug", 0.75, 0.05, 0.93, 0.04, 0.1),
                         cyl("mug1", "carrier_blue", 0.85, 0.1, 0.93, 0.04, 0.1)]
    return v


def refrigerator():
    """A domestic fridge-freezer: the white cabinet, the fridge door above the freezer door (+y),
    their handles."""
    return [box("cabinet", "fridge_white", 0, 0, 0.9, 0.6, 0.62, 1.8),
            box("seam", "cabinet_grey", 0, 0.311, 0.62, 0.58, 0.004, 0.01),
            box("handle_top", "cabinet_grey", 0.25, 0.33, 1.05, 0.03, 0.03, 0.4),
            box("handle_bottom", "cabinet_grey", 0.25, 0.33, 0.45, 0.03, 0.03, 0.25)]


def table(w=1.2, d=0.8):
    """The staff table: a laminate top on four steel legs, two mugs and a magazine on it."""
    return [box("top", "table_top", 0, 0, 0.73, w, d, 0.03)] + legs("steel", w / 2 - 0.05, d / 2 - 0.05, 0.715) + \
        [cyl("mug0", "mug", -0.3, 0.1, 0.795, 0.04, 0.1), cyl("mug1", "chair_red", 0.35, -0.15, 0.795, 0.04, 0.1),
         box("magazine", "leaflet_orange", 0.05, 0.05, 0.747, 0.22, 0.3, 0.005)]


def chair():
    """A plastic stacking chair on steel legs, its back at -y."""
    return [box("seat", "chair_red", 0, 0, 0.45, 0.44, 0.42, 0.03),
            box("back", "chair_red", 0, -0.2, 0.7, 0.42, 0.03, 0.36),
            box("back_post_l", "steel", -0.2, -0.2, 0.62, 0.02, 0.02, 0.3),
            box("back_post_r", "steel", 0.2, -0.2, 0.62, 0.02, 0.02, 0.3)] + legs("steel", 0.19, 0.18, 0.44, 0.02)


def locker(w=0.45, d=0.45, h=1.8):
    """A tall steel staff locker: the body, the door (+y) with vents, the handle and the number."""
    v = [box("body", "locker_blue", 0, 0, h / 2, w, d, h),
         box("door_seam", "dark_steel", 0, d / 2 + 0.001, h / 2, w - 0.04, 0.002, h - 0.04),
         box("handle", "dark_steel", w / 2 - 0.07, d / 2 + 0.01, 1.0, 0.03, 0.02, 0.12),
         box("number", "paper", 0, d / 2 + 0.003, h - 0.2, 0.08, 0.002, 0.05)]
    return v + [box(f"vent{i}", "dark_steel", 0, d / 2 + 0.003, h - 0.35 - 0.04 * i, 0.2, 0.002, 0.012) for i in range(4)]


# ---- the toilets ----
def toilet():
    """A toilet: the cistern against the wall (-y), the bowl, seat and lid in front of it."""
    return [box("cistern", "porcelain", 0, -0.22, 0.62, 0.42, 0.18, 0.4),
            cyl("bowl", "porcelain", 0, 0.05, 0.2, 0.19, 0.4),
            cyl("seat", "porcelain", 0, 0.06, 0.41, 0.21, 0.03),
            box("pedestal", "porcelain", 0, -0.1, 0.2, 0.25, 0.21, 0.4),
            box("flush", "steel", 0, -0.22, 0.83, 0.1, 0.06, 0.02)]


def walls():
    """The outer walls with the entrance (south); the reception's east wall; the corridor's south
    wall with the doors of the consultation rooms and toilets; its north wall with the doors of
    the pharmacy, the treatment area, consult 3 and the kennel ward; the partitions of the north
    rooms."""
    v, wall = base.wall_builder(H, T)

    def with_openings(fixed, along, lo, hi, openings, c, top=LINTEL):
        """A wall along x (along = 'x', y = fixed) or y with the openings (lo..hi) in it."""
        cut = lo
        for a, b in openings:
            if along == "x":
                wall(cut, fixed, a, fixed, c=c); wall(a, fixed, b, fixed, top, H, c=c)
            else:
                wall(fixed, cut, fixed, a, c=c); wall(fixed, a, fixed, b, top, H, c=c)
            cut = b
        if along == "x": wall(cut, fixed, hi, fixed, c=c)
        else: wall(fixed, cut, fixed, hi, c=c)

    with_openings(0, "x", 0, W, (FRONT_DOOR,), "plaster", 2.3)
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    # the south rooms: their dividing walls, the corridor's south wall with their doors
    for x in XC[:4]:
        wall(x, 0, x, YC0, c="white_tile" if x >= XC[2] else "partition")
    with_openings(YC0, "x", XRW, W, CONSULT_DOORS + TOILET_DOORS, "partition")
    # the corridor's north wall (and the reception's) with the doors of the north rooms
    with_openings(YC1, "x", 0, W, (PHARMACY_DOOR, TREATMENT_DOOR, CONSULT3_DOOR, KENNEL_DOOR), "partition")
    # the north rooms
    with_openings(XP, "y", YC1, D, (PHARMACY_BACK_DOOR, STAFF_DOOR), "partition")
    wall(0, YP, XP, YP, c="partition")
    with_openings(XT, "y", YC1, D, (SURGERY_DOOR,), "partition")
    wall(XT, YS, XK, YS, c="partition")
    wall(XK, YC1, XK, D, c="partition")
    return v


def floor():
    """The floor: a wood-effect floor in reception, blue-grey safety vinyl in the clinical rooms
    and the corridor, a green theatre vinyl in the surgery, resin in the kennel ward, white tiles
    in the toilets (thin layers over the slab)."""
    v = base.floor_slab("floor_clinic", "vinyl", W, D)
    v.append(box("reception", "woodfloor", XRW / 2, YC1 / 2, 0.0005, XRW, YC1, 0.001))
    v.append(box("surgery", "theatre_vinyl", (XT + XK) / 2, (YS + D) / 2, 0.0005, XK - XT, D - YS, 0.001))
    v.append(box("kennels", "kennel_resin", (XK + W) / 2, (YC1 + D) / 2, 0.0005, W - XK, D - YC1, 0.001))
    v.append(box("toilets", "tile", (XC[2] + W) / 2, YC0 / 2, 0.0005, W - XC[2], YC0, 0.001))
    return v


class Counter:
    """Numbers the instances of each class across the rooms (door_1, door_2, ...)."""

    def __init__(self, out):
        self.out, self.n = out, {}

    def __call__(self, cls, pose, vis, numbered=True):
        self.n[cls] = self.n.get(cls, 0) + 1
        name = f"{cls}_{self.n[cls]}" if numbered else cls
        self.out.append(base.model(name, pose, vis))


def reception(add):
    e0, e1 = FRONT_DOOR
    add("door", (e0 + 0.04, 0.47, 0, WEST), base.door())  # two leaves swung open into the room
    add("door", (e1 - 0.04, 0.47, 0, WEST), base.door())
    add("window", (1.1, T / 2 + 0.02, 1.6, N), base.window())
    add("window", (6.0, T / 2 + 0.02, 1.6, N), base.window())
    add("window", (T / 2 + 0.02, 2.2, 1.6, E), base.window())
    # the counter, the receptionists' computers and chairs behind it
    add("reception_counter", (2.7, 4.5, 0, S), reception_counter(3.0))  # clients south, staff north
    add("computer", (1.8, 4.63, 0.76, N), computer())  # the screens toward the receptionists
    add("computer", (3.5, 4.63, 0.76, N), computer())
    add("office_chair", (1.8, 5.45, 0, S), base.office_chair())
    add("office_chair", (3.9, 5.45, 0, S), base.office_chair())
    # waiting chairs: four on the west wall facing east, four under the front window facing north
    for y in (0.95, 1.6, 2.25, 2.9):
        add("waiting_chair", (T / 2 + 0.3, y, 0, E), waiting_chair())
    for x in (4.9, 5.55, 6.2, 6.85):
        add("waiting_chair", (x, T / 2 + 0.3, 0, N), waiting_chair())
    add("cat_carrier", (0.95, 1.3, 0, E), cat_carrier("carrier_blue"))      # on the floor by a chair
    add("cat_carrier", (5.55, 0.4, 0.49, E), cat_carrier("carrier_pink"))  # on a waiting chair
    add("pet_scale", (5.6, 3.4, 0, WEST), pet_scale())
    add("leaflet_rack", (T / 2 + 0.25, 3.9, 0, E), leaflet_rack())
    add("pet_food_shelf", (XRW - T / 2 - 0.2, 1.5, 0, WEST), pet_food_shelf(1.1))
    add("pet_food_shelf", (XRW - T / 2 - 0.2, 2.7, 0, WEST), pet_food_shelf(1.1))
    add("water_bowl", (7.4, 3.75, 0, N), water_bowl())
    add("trash_can", (4.45, T / 2 + 0.2, 0, N), pedal_bin())
    add("fire_extinguisher", (1.95, T / 2 + 0.1, 0, N), fire_extinguisher())


def consult_room(add, x0, y0, door):
    """Consultation rooms 1 and 2 (x0..x0+3, y0..4.5), the door in the north wall at the east."""
    d0, d1 = door
    add("door", (d1 - 0.04, YC0 - 0.47, 0, WEST), base.door())  # swung into the room, hinged east
    add("window", (x0 + 1.0, T / 2 + 0.02, 1.6, N), base.window())
    add("exam_table", (x0 + 1.45, 2.35, 0, N), exam_table())
    add("exam_stool", (x0 + 1.45, 1.6, 0, N), exam_stool())
    add("desk", (x0 + T / 2 + 0.36, 3.65, 0, E), base.desk())
    add("computer", (x0 + T / 2 + 0.35, 3.65, 0.75, E), computer())
    add("office_chair", (x0 + 1.15, 3.55, 0, WEST), base.office_chair())
    add("sink", (x0 + 2.3, T / 2 + 0.28, 0, N), sink())
    add("wall_cabinet", (x0 + 2.3, T / 2 + 0.18, 1.5, N), wall_cabinet())
    add("trash_can", (x0 + 2.75, 1.3, 0, N), pedal_bin())


def consult_room_3(add):
    """Consultation room 3 (x XT..XK, y YC1..YS), the door in the south wall (the corridor)."""
    d0, d1 = CONSULT3_DOOR
    add("door", (d1 - 0.04, YC1 + 0.47, 0, WEST), base.door())  # swung into the room, hinged east
    add("exam_table", (12.0, 7.6, 0, N), exam_table())
    add("exam_stool", (12.0, 6.9, 0, N), exam_stool())
    add("desk", (13.6, YS - T / 2 - 0.36, 0, S), base.desk())
    add("computer", (13.6, YS - T / 2 - 0.35, 0.75, S), computer())
    add("office_chair", (13.6, 7.95, 0, N), base.office_chair())
    add("sink", (XT + T / 2 + 0.28, 6.95, 0, E), sink())
    add("wall_cabinet", (XT + T / 2 + 0.18, 6.95, 1.5, E), wall_cabinet())
    add("trash_can", (XT + 0.3, 8.6, 0, N), pedal_bin())


def toilets(add):
    for (d0, d1), x0 in zip(TOILET_DOORS, XC[2:4]):
        add("door", (d1 - 0.04, YC0 - 0.47, 0, WEST), base.door())
        add("toilet", (x0 + 1.0, T / 2 + 0.31, 0, N), toilet())
        add("sink", (x0 + T / 2 + 0.28, 2.3, 0, E), sink())
        add("trash_can", (x0 + 1.6, 0.35, 0, N), pedal_bin())
    add("fire_extinguisher", (11.6, YC1 - T / 2 - 0.1, 0, S), fire_extinguisher())  # in the corridor


def pharmacy(add):
    """The pharmacy (x 0..XP, y YC1..YP): doors from reception (south) and the treatment area (east)."""
    d0, d1 = PHARMACY_DOOR
    add("door", (d1 - 0.04, YC1 + 0.47, 0, WEST), base.door())
    b0, b1 = PHARMACY_BACK_DOOR
    add("door", (XP - 0.47, b1 - 0.04, 0, N), base.door())
    for i, y in enumerate((6.8, 7.95, 9.1)):
        add("medicine_shelf", (T / 2 + 0.2, y, 0, E), medicine_shelf(1.1, i))
    add("vaccine_fridge", (1.5, YP - T / 2 - 0.32, 0, S), vaccine_fridge())
    add("counter", (2.8, YP - T / 2 - 0.31, 0, S), counter(1.2))
    add("computer", (2.8, YP - T / 2 - 0.3, 0.88, S), computer())


def staff_room(add):
    """The staff room (x 0..XP, y YP..D): its door into the treatment area."""
    add("door", (XP - 0.47, STAFF_DOOR[1] - 0.04, 0, N), base.door())
    add("window", (T / 2 + 0.02, 12.0, 1.6, E), base.window())
    add("kitchen_counter", (1.45, D - T / 2 - 0.31, 0, S), kitchen_counter(2.2))
    add("refrigerator", (3.0, D - T / 2 - 0.33, 0, S), refrigerator())
    add("table", (1.6, 11.9, 0, N), table())
    for x, y, yaw in ((1.3, 11.3, N), (1.9, 11.3, N), (1.3, 12.5, S), (1.9, 12.5, S)):
        add("chair", (x, y, 0, yaw), chair())
    for i in range(4):
        add("locker", (0.4 + 0.47 * i, YP + T / 2 + 0.23, 0, N), locker())
    add("trash_can", (3.6, YP + T / 2 + 0.2, 0, N), pedal_bin())


def treatment_area(add):
    """The treatment and prep area (x XP..XT, y YC1..D): the double door from the corridor."""
    t0, t1 = TREATMENT_DOOR
    add("door", (t0 + 0.04, YC1 + 0.47, 0, WEST), base.door())
    add("door", (t1 - 0.04, YC1 + 0.47, 0, WEST), base.door())
    wall_n = D - T / 2
    add("treatment_table", (6.6, 8.8, 0, N), treatment_table())
    add("treatment_table", (6.6, 11.3, 0, N), treatment_table())
    add("iv_pole", (7.7, 8.3, 0, N), iv_pole())
    add("iv_pole", (7.7, 11.9, 0, N), iv_pole())
    add("patient_monitor", (5.4, 11.3, 0, E), patient_monitor())
    add("instrument_trolley", (8.6, 10.0, 0, WEST), instrument_trolley())
    # the worktops: along the north wall (autoclave, microscope) and the east wall
    add("counter", (6.5, wall_n - 0.31, 0, S), counter(3.0))
    add("autoclave", (5.6, wall_n - 0.32, 0.88, S), autoclave())
    add("microscope", (7.2, wall_n - 0.3, 0.88, S), microscope())
    add("wall_cabinet", (5.6, wall_n - 0.18, 1.5, S), wall_cabinet())
    add("wall_cabinet", (7.4, wall_n - 0.18, 1.5, S), wall_cabinet())
    add("sink", (9.0, wall_n - 0.28, 0, S), sink())
    add("counter", (XT - T / 2 - 0.31, 13.1, 0, WEST), counter(1.5))
    add("oxygen_cylinder", (XP + T / 2 + 0.15, 10.1, 0, E), oxygen_cylinder())
    add("oxygen_cylinder", (XP + T / 2 + 0.15, 10.45, 0, E), oxygen_cylinder())
    add("clinical_waste_bin", (XP + T / 2 + 0.25, 13.6, 0, E), clinical_waste_bin())
    add("fire_extinguisher", (XP + T / 2 + 0.1, 7.0, 0, E), fire_extinguisher())


def surgery(add):
    """The surgery (x XT..XK, y YS..D), entered from the treatment area."""
    s0, s1 = SURGERY_DOOR
    add("door", (XT + 0.47, s1 - 0.04, 0, N), base.door())  # swung into the theatre, hinged north
    add("operating_table", (12.6, 11.7, 0, N), operating_table())
    add("surgical_lamp", (12.18, 11.7, 0, N), surgical_lamp())  # its head over the table
    add("anaesthesia_machine", (13.75, 12.85, 0, WEST), anaesthesia_machine())
    add("instrument_trolley", (12.5, 10.5, 0, N), instrument_trolley())
    add("patient_monitor", (13.9, 11.1, 0, WEST), patient_monitor())
    add("iv_pole", (11.6, 12.6, 0, N), iv_pole())
    add("scrub_sink", (11.5, D - T / 2 - 0.3, 0, S), scrub_sink())
    add("oxygen_cylinder", (XK - T / 2 - 0.15, 13.75, 0, WEST), oxygen_cylinder())
    add("oxygen_cylinder", (XK - T / 2 - 0.5, 13.75, 0, S), oxygen_cylinder())
    add("clinical_waste_bin", (XT + T / 2 + 0.25, 9.45, 0, E), clinical_waste_bin())


def kennel_ward(add):
    """The kennel ward (x XK..W, y YC1..D), entered from the corridor."""
    k0, k1 = KENNEL_DOOR
    add("door", (k0 + 0.04, YC1 + 0.47, 0, WEST), base.door())  # swung in, hinged west
    add("window", (16.6, D - T / 2 - 0.02, 1.8, S), base.window())
    for y in (7.65, 8.95, 10.25, 11.55, 12.85):
        add("dog_kennel", (W - T / 2 - 0.56, y, 0, WEST), dog_kennel())
    for y in (7.7, 8.45, 9.2):
        add("cat_cage", (XK + T / 2 + 0.31, y, 0, E), cat_cage(feet=True))
        add("cat_cage", (XK + T / 2 + 0.31, y, 0.7, E), cat_cage())
    add("washing_machine", (15.0, D - T / 2 - 0.31, 0, S), washing_machine())
    add("iv_pole", (15.2, 11.2, 0, N), iv_pole())
    add("trash_can", (XK + T / 2 + 0.2, 10.2, 0, N), pedal_bin())


def main():
    out = [base.model("walls", (0, 0, 0, 0), walls()),
           base.model("floor", (0, 0, 0, 0), floor()),
           base.model("ceiling", (0, 0, 0, 0), base.ceiling_slab(W, D, H))]
    add = Counter(out)
    reception(add)
    consult_room(add, XC[0], 0, CONSULT_DOORS[0])
    consult_room(add, XC[1], 0, CONSULT_DOORS[1])
    toilets(add)
    pharmacy(add)
    staff_room(add)
    treatment_area(add)
    consult_room_3(add)
    surgery(add)
    kennel_ward(add)
    warm, cool = "0.85 0.8 0.7", "0.82 0.83 0.82"
    lights = [base.point_light(name, x, y, H - 0.25, rgb)
              for name, x, y, rgb in (("light_reception_w", 2.2, 2.5, warm), ("light_reception_e", 5.8, 2.5, warm),
                                      ("light_consult_1", 9.5, 2.3, cool), ("light_consult_2", 12.5, 2.3, cool),
                                      ("light_toilets", 16.0, 2.3, cool), ("light_corridor", 13.0, 5.25, cool),
                                      ("light_pharmacy", 2.0, 8.0, cool), ("light_staff", 2.0, 12.0, warm),
                                      ("light_treatment_s", 7.2, 8.5, cool), ("light_treatment_n", 7.2, 12.0, cool),
                                      ("light_consult_3", 12.5, 7.5, cool), ("light_surgery", 12.5, 11.5, cool),
                                      ("light_kennels_s", 16.2, 8.5, cool), ("light_kennels_n", 16.2, 12.0, cool))]
    print(base.world_sdf("semsplat_vetclinic", """The semsplat vet clinic: a small-animal veterinary practice of 18 m x 14 m on one floor
     (south: the reception and waiting area with the reception counter, waiting chairs, a pet scale,
     a leaflet rack, pet food shelves, a water bowl and cat carriers; two consultation rooms and two
     toilets off the corridor; north: the pharmacy and the staff room, the treatment and prep area,
     a third consultation room, the surgery with the operating table, the surgical lamp and the
     anaesthesia machine, the kennel ward with dog kennels and cat cages) for measuring on a world
     nobody tuned on. Generated by vetclinic_models/make_vetclinic.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
