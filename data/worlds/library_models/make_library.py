#!/usr/bin/env python3
"""Writes data/worlds/library.world: a public library of 20 m x 14 m on one floor, for measuring the
semantic stack on a world nobody tuned on.

South of the building (y < 4.6), west to east: the children's corner behind low half-walls (a low
bookshelf, picture book bins, a kids' table with four kids' chairs, bean bags, a toy box); the
entrance lobby with the main entrance (two door leaves) in the south wall, three security gate
pedestals inside it, the book return slot in the wall beside the entrance, a notice board, a
new-books display table, a self-checkout kiosk and the circulation desk with the librarian's office
chair, monitor and keyboard; the staff workroom behind the desk (a work table, the staff computer
desk, filing cabinets, a book cart); the toilets (two toilet cubicles, two sinks with mirrors, a
hand dryer).
North of it (y > 4.6), west to east: the stacks (five double-sided rows of bookshelves and a row
against the west wall, two catalogue terminals at the row ends, step stools, a book cart, the fire
exit in the north wall with the exit sign over it); the reading area (four reading tables with
chairs and green reading lamps); the public computers north of it (five computer desks with
monitors, keyboards and office chairs, a printer and a photocopier); the lounge by the east windows
(two armchairs, a floor lamp, the magazine rack, a drinking fountain) and two study rooms, each
with a study table, four chairs and a whiteboard. Fire extinguishers, waste bins, potted plants.

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("reading_lamp_3" ->
"reading lamp"). The primitives and the SDF writing are the office generator's.
Run: python3 data/worlds/library_models/make_library.py > data/worlds/library.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, plant)

W, D, H = 20.0, 14.0, 3.0  # floor width (x), depth (y), wall height
T = 0.1                    # wall thickness
YS = 4.6                   # the line between the south rooms and the open north floor
XK = 6.0                   # the children's corner's east half-wall (x)
XST, XWC = 12.0, 16.4      # the staff workroom (x XST..XWC) and the toilets (x > XWC), y < YS
XR = 16.4                  # the study rooms' west wall (north, x > XR), y > YSR
YSR, YSM = 8.6, 11.3       # the study rooms' south wall and the wall between them

MAIN_ENTRANCE = (8.6, 10.4)   # x, south wall
FIRE_EXIT = (8.9, 10.1)       # x, north wall
STAFF_DOOR = (3.6, 4.5)       # y, wall x = XST (behind the circulation desk)
TOILET_DOOR = (16.8, 17.7)    # x, wall y = YS
STUDY_DOOR_1 = (8.9, 9.8)     # y, wall x = XR
STUDY_DOOR_2 = (11.6, 12.5)   # y, wall x = XR
HALF_WALL = 1.0               # the children's corner's half-walls

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "lino": "0.6 0.58 0.52", "partition": "0.86 0.85 0.8", "kids_wall": "0.95 0.85 0.55",
    "oak": "0.58 0.42 0.26", "beech": "0.8 0.66 0.46", "laminate": "0.88 0.86 0.8",
    "steel": "0.72 0.74 0.76", "shelf_grey": "0.68 0.7 0.72", "brass": "0.78 0.63 0.3",
    "lamp_green": "0.1 0.45 0.25", "book_red": "0.62 0.14 0.12", "book_blue": "0.14 0.24 0.52",
    "book_green": "0.18 0.42 0.24", "book_ochre": "0.78 0.58 0.2", "book_cream": "0.9 0.86 0.74",
    "book_black": "0.12 0.12 0.14", "book_teal": "0.18 0.48 0.5", "book_plum": "0.42 0.2 0.38",
    "cork": "0.7 0.52 0.32", "paper": "0.96 0.96 0.92", "note_yellow": "0.95 0.88 0.35",
    "note_pink": "0.95 0.6 0.7", "counter_front": "0.36 0.3 0.26", "counter_top": "0.86 0.83 0.77",
    "screen": "0.08 0.1 0.14", "kiosk_blue": "0.2 0.36 0.6", "acrylic": "0.8 0.9 0.95",
    "gate_grey": "0.82 0.83 0.84", "signal_green": "0.1 0.7 0.3", "upholstery": "0.5 0.15 0.12",
    "cushion": "0.6 0.22 0.16", "toy_red": "0.9 0.2 0.15", "toy_yellow": "0.98 0.8 0.1",
    "toy_blue": "0.15 0.45 0.85", "toy_green": "0.3 0.7 0.25", "bean_orange": "0.95 0.5 0.15",
    "bean_purple": "0.5 0.3 0.7", "copier_grey": "0.85 0.85 0.83", "porcelain": "0.97 0.97 0.97",
    "tile": "0.85 0.88 0.88", "mirror": "0.8 0.85 0.88", "fire_door": "0.55 0.58 0.6",
    "extinguisher_red": "0.8 0.08 0.06", "exit_green": "0.05 0.6 0.25", "rubber": "0.1 0.1 0.1",
    "bin_grey": "0.35 0.37 0.4", "return_blue": "0.18 0.3 0.55", "magazine_a": "0.85 0.3 0.25",
    "magazine_b": "0.25 0.55 0.8", "magazine_c": "0.95 0.75 0.2", "magazine_d": "0.4 0.7 0.45",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned, along_x, castors = base.turned, base.along_x, base.castors

BOOKS = ("book_red", "book_blue", "book_green", "book_ochre", "book_cream", "book_black", "book_teal",
         "book_plum")


# ---- the things (local frames: x right, y forward = the side a user faces, z up) ----
def book_run(tag, x0, x1, y, z, depth, seed, n=6):
    """A run of books standing on a shelf from x0 to x1 (their spines along +y or -y), in blocks of
    a few colours and heights."""
    v, gap = [], 0.015
    w = (x1 - x0) / n
    for k in range(n):
        h = (0.24, 0.29, 0.21, 0.27, 0.25, 0.3, 0.22)[(seed + k) % 7]
        if (seed * 3 + k) % 11 == 5:   # a gap where books are out on loan
            continue
        v.append(box(f"books_{tag}_{k}", BOOKS[(seed + 2 * k) % len(BOOKS)], x0 + w * (k + 0.5), y,
                     z + h / 2, w - gap, depth, h))
    return v


def bookshelf(length=1.8, h=2.0, levels=5, double=True, seed=0):
    """A library shelving unit of steel-grey ends and oak shelves, filled with books: double-sided
    (books on both faces, a spine panel down the middle) for the free-standing rows, single-sided
    (a back at -y) against a wall."""
    depth = 0.6 if double else 0.34
    c = "shelf_grey"
    v = [box("end_l", c, -length / 2 + 0.015, 0, h / 2, 0.03, depth, h),
         box("end_r", c, length / 2 - 0.015, 0, h / 2, 0.03, depth, h),
         box("top", c, 0, 0, h - 0.015, length, depth, 0.03),
         box("kick", c, 0, 0, 0.05, length - 0.06, depth - 0.04, 0.1),
         box("spine" if double else "back", c, 0, 0 if double else -depth / 2 + 0.01, h / 2, length - 0.06,
             0.02, h)]
    pitch = (h - 0.15) / levels
    for i in range(levels):
        z = 0.1 + pitch * i
        v.append(box(f"shelf{i}", "oak", 0, 0, z, length - 0.06, depth - 0.02, 0.02))
        faces = ((1, 0.15), (-1, -0.15)) if double else ((1, 0.02),)
        for f, (sgn, yc) in enumerate(faces):
            v += book_run(f"{i}_{f}", -length / 2 + 0.05, length / 2 - 0.05, yc, z + 0.01,
                          0.22 if double else 0.24, seed + 3 * i + 5 * f)
    return v


def circulation_desk(length=2.6, depth=0.8):
    """The loan desk: a tall front to the visitors (+y) with a ledge, the librarian's work top behind
    it, a barcode scanner and a stack of returned books on the top."""
    return [box("front", "counter_front", 0, depth / 2 - 0.03, 0.55, length, 0.06, 1.1),
            box("ledge", "counter_top", 0, depth / 2 - 0.12, 1.12, length + 0.05, 0.28, 0.04),
            box("work_top", "counter_top", 0, -0.05, 0.74, length, depth - 0.1, 0.04),
            box("side_l", "counter_front", -length / 2, 0, 0.55, 0.04, depth, 1.1),
            box("side_r", "counter_front", length / 2, 0, 0.55, 0.04, depth, 1.1),
            box("drawers", "counter_front", length / 2 - 0.3, -0.1, 0.36, 0.5, 0.5, 0.72),
            box("scanner", "black", 0.55, depth / 2 - 0.12, 1.17, 0.08, 0.12, 0.06),
            box("returns0", "book_red", -0.8, 0.05, 0.8, 0.22, 0.3, 0.05),
            box("returns1", "book_blue", -0.8, 0.05, 0.85, 0.2, 0.28, 0.05),
            box("returns2", "book_ochre", -0.8, 0.05, 0.9, 0.23, 0.3, 0.05),
            box("sign", "return_blue", 0, depth / 2 + 0.005, 0.9, 0.8, 0.01, 0.2)]


def book_return():
    """The book return slot through the wall beside the entrance (the wall behind at -y): a steel
    plate with the slot and a blue sign, the chute, and the wheeled depressible bin under it."""
    return [box("plate", "steel", 0, 0.01, 1.05, 0.6, 0.02, 0.45),
            box("slot", "black", 0, 0.022, 1.08, 0.42, 0.006, 0.05),
            box("sign", "return_blue", 0, 0.022, 1.22, 0.4, 0.006, 0.1),
            box("chute", "steel", 0, 0.12, 0.86, 0.46, 0.2, 0.1),
            box("bin", "return_blue", 0, 0.28, 0.4, 0.6, 0.5, 0.62),
            box("bin_rim", "steel", 0, 0.28, 0.72, 0.62, 0.52, 0.03),
            box("bin_books", "book_ochre", 0, 0.28, 0.66, 0.5, 0.4, 0.08)] + \
        [sph(f"castor{i}", "rubber", dx, 0.28 + dy, 0.04, 0.04)
         for i, (dx, dy) in enumerate(((-0.25, -0.2), (0.25, -0.2), (-0.25, 0.2), (0.25, 0.2)))]


def self_checkout():
    """A self-service loan kiosk: a pedestal, a slanted touch screen facing the user (+y) and the
    pad the books are laid on to be scanned, a receipt slot."""
    return [box("pedestal", "kiosk_blue", 0, 0, 0.48, 0.45, 0.4, 0.96),
            box("foot", "dark_metal", 0, 0, 0.02, 0.55, 0.5, 0.04),
            box("pad", "dark_metal", 0, 0.05, 0.98, 0.42, 0.34, 0.04),
            turned(box("head", "grey_plastic", 0, -0.12, 1.28, 0.45, 0.06, 0.36), "-0.3 0 0"),
            turned(box("screen", "screen", 0, -0.085, 1.29, 0.38, 0.004, 0.28), "-0.3 0 0"),
            box("receipt", "black", 0.15, 0.2, 0.85, 0.1, 0.01, 0.02)]


def security_gate():
    """One pedestal of the anti-theft gates at the entrance: a clear panel on a grey post, long
    along the way people walk through (y), with the alarm light on top."""
    return [box("foot", "gate_grey", 0, 0, 0.03, 0.16, 0.75, 0.06),
            box("post_s", "gate_grey", 0, -0.33, 0.78, 0.08, 0.08, 1.5),
            box("post_n", "gate_grey", 0, 0.33, 0.78, 0.08, 0.08, 1.5),
            box("panel", "acrylic", 0, 0, 0.8, 0.03, 0.6, 1.3),
            box("cap", "gate_grey", 0, 0, 1.55, 0.09, 0.76, 0.04),
            box("light", "signal_green", 0, 0, 1.58, 0.05, 0.3, 0.02)]


def notice_board(w=1.0, h=0.8):
    """A cork board on the wall (behind at -y) in an oak frame, with posters and notes pinned to it."""
    v = [box("frame", "oak", 0, 0, 0, w + 0.06, 0.03, h + 0.06),
         box("cork", "cork", 0, 0.016, 0, w, 0.004, h)]
    pinned = (("paper", -0.28, 0.18, 0.3, 0.36), ("note_yellow", 0.05, 0.22, 0.18, 0.18),
              ("note_pink", 0.3, 0.15, 0.2, 0.26), ("paper", -0.1, -0.2, 0.34, 0.24),
              ("kiosk_blue", 0.3, -0.2, 0.22, 0.3))
    v += [box(f"pinned{i}", c, x * w, 0.02, z * h, sx, 0.003, sz) for i, (c, x, z, sx, sz) in enumerate(pinned)]
    return v


def book_display():
    """The new-books display: a low table with books stood up on it, faces out to both sides, and a
    sign on a stand in the middle."""
    v = [box("top", "beech", 0, 0, 0.72, 1.2, 0.7, 0.04)] + legs("dark_metal", 0.55, 0.3, 0.7, 0.04)
    for i in range(4):
        for side, (y, roll) in enumerate(((0.15, "-0.25 0 0"), (-0.15, "0.25 0 0"))):
            v.append(turned(box(f"book{i}_{side}", BOOKS[(i * 3 + side) % len(BOOKS)], -0.42 + 0.28 * i, y, 0.87,
                                0.18, 0.03, 0.26), roll))
    return v + [box("sign_post", "steel", 0, 0, 0.85, 0.02, 0.02, 0.22),
                box("sign", "return_blue", 0, 0, 1.0, 0.3, 0.01, 0.12)]


def step_stool():
    """A round rolling kick step for the top shelves: a steel drum with a rubber tread."""
    return [cyl("ring", "rubber", 0, 0, 0.02, 0.22, 0.04),
            cyl("drum", "steel", 0, 0, 0.2, 0.2, 0.32),
            cyl("tread", "rubber", 0, 0, 0.38, 0.16, 0.04)]


def book_cart():
    """A library book trolley: two sloped shelves of books on a frame with castors and a push
    handle, long along x."""
    v = [box("frame_l", "steel", -0.44, 0, 0.5, 0.03, 0.4, 0.9),
         box("frame_r", "steel", 0.44, 0, 0.5, 0.03, 0.4, 0.9),
         box("deck", "oak", 0, 0, 0.18, 0.86, 0.38, 0.02),
         box("handle", "steel", 0.52, 0, 0.92, 0.02, 0.36, 0.02)]
    for i, z in enumerate((0.5, 0.82)):
        v.append(turned(box(f"shelf{i}", "oak", 0, 0, z, 0.86, 0.38, 0.02), "0.2 0 0"))
        v += [turned(box(f"books{i}_{k}", BOOKS[(i * 4 + k) % len(BOOKS)], -0.3 + 0.2 * k, 0, z + 0.12, 0.17, 0.24,
                         0.22), "0.2 0 0") for k in range(4)]
    v += book_run("deck", -0.4, 0.4, 0, 0.19, 0.24, 3, 4)
    return v + castors(0.38, 0.16)


def catalog_terminal():
    """A standing catalogue terminal for finding a book: a foot, a post, a tilted screen facing
    the user (+y) and a small keyboard shelf."""
    return [box("foot", "dark_metal", 0, 0, 0.02, 0.5, 0.5, 0.04),
            box("post", "shelf_grey", 0, -0.05, 0.55, 0.14, 0.14, 1.05),
            box("shelf", "shelf_grey", 0, 0.1, 1.02, 0.5, 0.28, 0.03),
            box("keys", "black", 0, 0.12, 1.045, 0.4, 0.13, 0.02),
            turned(box("case", "black", 0, -0.05, 1.36, 0.46, 0.06, 0.34), "-0.25 0 0"),
            turned(box("screen", "screen", 0, -0.015, 1.365, 0.4, 0.004, 0.27), "-0.25 0 0"),
            box("label", "return_blue", 0, -0.05, 1.6, 0.3, 0.02, 0.08)]


def reading_table(w=2.0, d=1.0):
    return [box("top", "oak", 0, 0, 0.74, w, d, 0.05),
            box("apron", "oak", 0, 0, 0.67, w - 0.2, d - 0.2, 0.08)] + legs("oak", w / 2 - 0.08, d / 2 - 0.08, 0.72, 0.07)


def chair():
    """A wooden chair, its back at -y (the person faces +y)."""
    return [box("seat", "beech", 0, 0, 0.45, 0.44, 0.42, 0.04),
            box("rail", "beech", 0, -0.2, 0.62, 0.42, 0.03, 0.05),
            box("back", "beech", 0, -0.2, 0.84, 0.42, 0.03, 0.12),
            box("post_l", "beech", -0.19, -0.2, 0.7, 0.03, 0.03, 0.5),
            box("post_r", "beech", 0.19, -0.2, 0.7, 0.03, 0.03, 0.5)] + legs("beech", 0.19, 0.18, 0.43, 0.03)


def reading_lamp():
    """A green-shaded brass banker's lamp standing on a table, the shade long along x."""
    return [box("base", "brass", 0, 0, 0.015, 0.22, 0.12, 0.03),
            cyl("stem", "brass", 0, -0.02, 0.2, 0.012, 0.36),
            along_x(cyl("shade", "lamp_green", 0, 0.02, 0.39, 0.06, 0.32)),
            along_x(cyl("tube", "lamp_shade", 0, 0.03, 0.35, 0.02, 0.28))]


def armchair():
    """A deep upholstered armchair, its back at -y."""
    return [box("base", "upholstery", 0, 0, 0.2, 0.82, 0.8, 0.3),
            box("cushion", "cushion", 0, 0.06, 0.4, 0.6, 0.64, 0.12),
            box("back", "upholstery", 0, -0.32, 0.65, 0.82, 0.18, 0.62),
            box("arm_l", "upholstery", -0.35, 0.02, 0.5, 0.14, 0.76, 0.3),
            box("arm_r", "upholstery", 0.35, 0.02, 0.5, 0.14, 0.76, 0.3)] + \
        [cyl(f"foot{i}", "oak", sx * 0.34, sy * 0.32, 0.025, 0.03, 0.05)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


def floor_lamp():
    return [cyl("base", "dark_metal", 0, 0, 0.015, 0.16, 0.03),
            cyl("pole", "brass", 0, 0, 0.8, 0.015, 1.56),
            cyl("shade", "lamp_shade", 0, 0, 1.55, 0.2, 0.28)]


def magazine_rack(w=1.1):
    """The periodicals rack: three tiers of sloped shelves showing the current magazines face out
    (+y), a shelf of back issues and newspapers at the bottom, its back at -y."""
    v = [box("back", "oak", 0, -0.18, 0.75, w, 0.03, 1.5),
         box("side_l", "oak", -w / 2, 0, 0.75, 0.03, 0.4, 1.5),
         box("side_r", "oak", w / 2, 0, 0.75, 0.03, 0.4, 1.5),
         box("bottom", "oak", 0, 0, 0.1, w, 0.38, 0.03),
         box("papers", "paper", 0, 0, 0.16, w - 0.1, 0.3, 0.1)]
    covers = ("magazine_a", "magazine_b", "magazine_c", "magazine_d", "paper", "toy_red")
    for i in range(3):
        z = 0.55 + 0.35 * i
        v.append(turned(box(f"tier{i}", "oak", 0, -0.02, z, w - 0.04, 0.03, 0.32), "-0.35 0 0"))
        v += [turned(box(f"magazine{i}_{k}", covers[(i * 2 + k) % len(covers)], -w / 2 + w * (k + 0.5) / 4, 0.0,
                         z + 0.02, w / 4 - 0.05, 0.01, 0.28), "-0.35 0 0") for k in range(4)]
    return v


def computer_desk(w=1.4, d=0.7):
    """A desk for a computer: laminate top on metal legs, a modesty panel at the back (-y), the
    computer tower on the floor beside the knee space; the user sits at +y."""
    return [box("top", "laminate", 0, 0, 0.73, w, d, 0.03),
            box("modesty", "shelf_grey", 0, -d / 2 + 0.03, 0.45, w - 0.1, 0.02, 0.45),
            box("tower", "black", w / 2 - 0.2, -0.05, 0.22, 0.2, 0.45, 0.42),
            box("tower_light", "kiosk_blue", w / 2 - 0.2, 0.175, 0.38, 0.05, 0.004, 0.01),
            box("mouse", "black", 0.38, 0.15, 0.755, 0.06, 0.1, 0.02)] + legs("dark_metal", w / 2 - 0.04, d / 2 - 0.04, 0.72, 0.04)


def printer():
    """A shared office laser printer on its own small cabinet, the output tray facing +y."""
    return [box("cabinet", "shelf_grey", 0, 0, 0.35, 0.55, 0.5, 0.7),
            box("body", "grey_plastic", 0, 0, 0.88, 0.46, 0.42, 0.36),
            box("output", "dark_metal", 0, 0.05, 1.07, 0.32, 0.22, 0.02),
            box("paper_out", "paper", 0, 0.05, 1.085, 0.21, 0.28, 0.01),
            box("panel", "screen", 0.15, 0.2, 1.0, 0.1, 0.02, 0.06)]


def photocopier():
    """A big floor-standing photocopier: paper drawers below, the glass and its lid on top, the
    control panel at the front (+y), the sorter tray at one side."""
    v = [box("body", "copier_grey", 0, 0, 0.5, 0.65, 0.6, 1.0),
         box("lid", "grey_plastic", 0, 0, 1.03, 0.63, 0.55, 0.06),
         box("panel", "dark_metal", 0.15, 0.27, 1.02, 0.3, 0.1, 0.04),
         box("touch", "screen", 0.15, 0.3, 1.045, 0.2, 0.05, 0.01),
         box("tray", "grey_plastic", 0.4, 0, 0.75, 0.18, 0.4, 0.02),
         box("copies", "paper", 0.42, 0, 0.765, 0.16, 0.3, 0.02)]
    return v + [box(f"drawer{i}", "dark_metal", 0, 0.302, 0.15 + 0.18 * i, 0.6, 0.004, 0.01) for i in range(4)]


def study_table(w=1.6, d=0.9):
    return [box("top", "laminate", 0, 0, 0.73, w, d, 0.04)] + legs("dark_metal", w / 2 - 0.06, d / 2 - 0.06, 0.71, 0.05)


def picture_book_bin(w=0.8, d=0.55):
    """A low browser box of picture books for little children: books stand in two rows, covers
    to the front (+y), so a child can flip through them."""
    v = [box("base", "kids_wall", 0, 0, 0.12, w, d, 0.24),
         box("side_l", "toy_blue", -w / 2 + 0.015, 0, 0.3, 0.03, d, 0.36),
         box("side_r", "toy_blue", w / 2 - 0.015, 0, 0.3, 0.03, d, 0.36),
         box("front", "toy_green", 0, d / 2 - 0.015, 0.32, w, 0.03, 0.16),
         box("divider", "toy_blue", 0, 0, 0.3, w, 0.02, 0.36)]
    picture = ("toy_red", "toy_yellow", "book_teal", "toy_green", "bean_orange", "toy_blue")
    for r, y in enumerate((0.12, -0.14)):
        v += [turned(box(f"book{r}_{k}", picture[(r + k) % len(picture)], -w / 2 + w * (k + 0.5) / 4, y, 0.4,
                         w / 4 - 0.03, 0.02, 0.3), "-0.2 0 0") for k in range(4)]
    return v


def kids_table():
    """A low round table for children, on four stubby legs."""
    return [cyl("top", "toy_yellow", 0, 0, 0.5, 0.5, 0.04)] + legs("toy_blue", 0.25, 0.25, 0.48, 0.05)


def kids_chair():
    """A small plastic chair for a child, its back at -y."""
    return [box("seat", "toy_red", 0, 0, 0.3, 0.3, 0.3, 0.03),
            box("back", "toy_red", 0, -0.14, 0.46, 0.3, 0.02, 0.26)] + legs("toy_blue", 0.13, 0.13, 0.29, 0.03)


def bean_bag(c="bean_orange"):
    """A slumped bean bag: a wide round base and a softer top."""
    return [cyl("base", c, 0, 0, 0.1, 0.42, 0.2), sph("body", c, 0, 0, 0.28, 0.36), sph("top", c, 0, -0.08, 0.48, 0.22)]


def toy_box():
    """A painted wooden toy chest against a wall (behind at -y), a ball and blocks on its lid."""
    return [box("chest", "toy_blue", 0, 0, 0.24, 0.8, 0.45, 0.48),
            box("lid", "toy_yellow", 0, 0, 0.5, 0.84, 0.48, 0.04),
            sph("ball", "toy_red", -0.2, 0, 0.63, 0.1),
            box("block0", "toy_green", 0.15, 0.05, 0.57, 0.1, 0.1, 0.1),
            box("block1", "bean_orange", 0.28, -0.05, 0.57, 0.1, 0.1, 0.1)]


def work_table(w=1.8, d=0.9):
    """The staff's processing table, with a pile of books being covered and labelled."""
    return [box("top", "laminate", 0, 0, 0.74, w, d, 0.04),
            box("pile0", "book_green", -0.5, 0.1, 0.79, 0.24, 0.32, 0.06),
            box("pile1", "book_plum", -0.5, 0.1, 0.85, 0.22, 0.3, 0.06),
            box("roll", "acrylic", 0.3, 0.1, 0.8, 0.35, 0.08, 0.08)] + legs("dark_metal", w / 2 - 0.05, d / 2 - 0.05, 0.72, 0.05)


def toilet():
    """A toilet: the cistern against the wall (-y), the bowl and seat in front of it."""
    return [box("cistern", "porcelain", 0, -0.22, 0.62, 0.42, 0.18, 0.4),
            cyl("bowl", "porcelain", 0, 0.05, 0.2, 0.19, 0.4),
            cyl("seat", "porcelain", 0, 0.06, 0.41, 0.21, 0.03),
            box("flush", "steel", 0, -0.22, 0.83, 0.1, 0.06, 0.02)]


def sink():
    """A wall-hung wash basin (the wall behind at -y) with its tap."""
    return [box("basin", "porcelain", 0, 0.15, 0.8, 0.5, 0.4, 0.15),
            box("bowl", "tile", 0, 0.17, 0.86, 0.38, 0.28, 0.04),
            cyl("tap", "steel", 0, 0.0, 0.94, 0.02, 0.14),
            box("spout", "steel", 0, 0.06, 1.0, 0.03, 0.12, 0.02),
            cyl("trap", "steel", 0, 0.05, 0.55, 0.03, 0.35)]


def mirror(w=0.5, h=0.7):
    """A washroom mirror on the wall (behind at -y)."""
    return [box("frame", "steel", 0, 0, 0, w + 0.04, 0.02, h + 0.04),
            box("glass", "mirror", 0, 0.011, 0, w, 0.004, h)]


def hand_dryer():
    """A wall-mounted hand dryer (the wall behind at -y), its nozzle pointing down."""
    return [box("body", "porcelain", 0, 0.08, 1.2, 0.28, 0.16, 0.3),
            box("nozzle", "steel", 0, 0.1, 1.03, 0.08, 0.08, 0.05)]


def water_fountain():
    """A wall-mounted drinking fountain (the wall behind at -y): a steel basin with its bubbler and
    push button, and a bottle filler above it."""
    return [box("back", "steel", 0, 0.01, 1.05, 0.45, 0.02, 0.9),
            box("basin", "steel", 0, 0.18, 0.88, 0.42, 0.34, 0.12),
            box("bowl", "dark_metal", 0, 0.2, 0.94, 0.3, 0.22, 0.01),
            cyl("bubbler", "steel", 0.05, 0.22, 0.97, 0.015, 0.05),
            box("button", "black", 0, 0.355, 0.88, 0.06, 0.01, 0.04),
            box("filler", "steel", 0, 0.08, 1.38, 0.3, 0.14, 0.22),
            box("sensor", "black", 0, 0.151, 1.4, 0.08, 0.004, 0.04)]


def fire_extinguisher():
    """A red extinguisher on its wall bracket (the wall behind at -y)."""
    return [box("bracket", "dark_metal", 0, -0.08, 0.85, 0.1, 0.02, 0.3),
            cyl("body", "extinguisher_red", 0, 0, 0.8, 0.08, 0.5),
            sph("shoulder", "extinguisher_red", 0, 0, 1.05, 0.08),
            cyl("head", "black", 0, 0, 1.15, 0.025, 0.08),
            box("handle", "black", 0, 0.04, 1.19, 0.03, 0.12, 0.02),
            turned(cyl("hose", "black", 0.07, 0.03, 1.0, 0.012, 0.3), "0 0.3 0")]


def exit_sign():
    """The green illuminated exit sign over a door (the wall behind at -y): the running man."""
    return [box("body", "exit_green", 0, 0, 0, 0.42, 0.05, 0.16),
            box("man", "white", -0.1, 0.026, 0, 0.06, 0.004, 0.11),
            box("arrow", "white", 0.08, 0.026, 0, 0.16, 0.004, 0.04)]


def waste_bin():
    return [cyl("body", "bin_grey", 0, 0, 0.3, 0.17, 0.6), cyl("rim", "dark_metal", 0, 0, 0.61, 0.175, 0.02)]


def fire_exit_door(width=1.2):
    """The fire exit: two closed steel leaves in the opening with push bars, seen from +y."""
    half = width / 2
    return [box("leaf_l", "fire_door", -half / 2, 0, 1.05, half - 0.01, 0.05, 2.1),
            box("leaf_r", "fire_door", half / 2, 0, 1.05, half - 0.01, 0.05, 2.1),
            box("bar_l", "steel", -half / 2, 0.05, 1.0, half - 0.12, 0.04, 0.05),
            box("bar_r", "steel", half / 2, 0.05, 1.0, half - 0.12, 0.04, 0.05)]


# ---- the building ----
def walls():
    """The outer walls with the main entrance and the fire exit; the staff workroom's and the
    toilets' partitions, the toilet cubicles; the study rooms; the children's corner's half-walls."""
    v, wall = base.wall_builder(H, T)
    e0, e1 = MAIN_ENTRANCE
    wall(0, 0, e0, 0); wall(e1, 0, W, 0); wall(e0, 0, e1, 0, 2.3, H)
    f0, f1 = FIRE_EXIT
    wall(0, D, f0, D); wall(f1, D, W, D); wall(f0, D, f1, D, 2.2, H)
    wall(0, 0, 0, D); wall(W, 0, W, D)
    p = "partition"
    # the staff workroom: its door in the west partition, behind the circulation desk
    s0, s1 = STAFF_DOOR
    wall(XST, 0, XST, s0, c=p); wall(XST, s1, XST, YS, c=p); wall(XST, s0, XST, s1, 2.1, H, c=p)
    wall(XST, YS, XWC, YS, c=p)
    # the toilets: the wall shared with the workroom, the door in the north partition, two cubicles
    wall(XWC, 0, XWC, YS, c=p)
    t0, t1 = TOILET_DOOR
    wall(XWC, YS, t0, YS, c=p); wall(t1, YS, W, YS, c=p); wall(t0, YS, t1, YS, 2.1, H, c=p)
    wall(18.6, 1.5, W, 1.5, 0, 2.0, c=p); wall(18.6, 3.0, W, 3.0, 0, 2.0, c=p)
    # the study rooms: the west wall with both doors, the south wall, the wall between them
    a0, a1 = STUDY_DOOR_1
    b0, b1 = STUDY_DOOR_2
    wall(XR, YSR, XR, a0, c=p); wall(XR, a1, XR, b0, c=p); wall(XR, b1, XR, D, c=p)
    wall(XR, a0, XR, a1, 2.1, H, c=p); wall(XR, b0, XR, b1, 2.1, H, c=p)
    wall(XR, YSR, W, YSR, c=p); wall(XR, YSM, W, YSM, c=p)
    # the children's corner: half-walls to the stacks (north) and along part of the lobby (east)
    wall(0, YS, 4.6, YS, 0, HALF_WALL, c="kids_wall"); wall(XK, 3.0, XK, YS, 0, HALF_WALL, c="kids_wall")
    return v


class World:
    def __init__(self):
        self.out = base.shell(walls(), "floor_library", "lino", W, D, H)

    def add(self, name, pose, vis):
        self.out.append(base.model(name, pose, vis))


def childrens_corner(w):
    w.add("window_1", (1.6, T / 2 + 0.02, 1.5, N), base.window())
    w.add("window_2", (4.3, T / 2 + 0.02, 1.5, N), base.window())
    w.add("window_3", (T / 2 + 0.02, 0.95, 1.6, E), base.window())
    w.add("bookshelf_1", (T / 2 + 0.18, 2.5, 0, E), bookshelf(1.6, 1.2, 3, False, 11))  # a low one
    for i, x in enumerate((1.0, 2.1, 3.2), 1):
        w.add(f"picture_book_bin_{i}", (x, YS - T / 2 - 0.3, 0, S), picture_book_bin())
    w.add("kids_table", (2.6, 2.1, 0, N), kids_table())
    for i, (x, y, yaw) in enumerate(((1.95, 2.1, E), (3.25, 2.1, WEST), (2.6, 1.45, N), (2.6, 2.75, S)), 1):
        w.add(f"kids_chair_{i}", (x, y, 0, yaw), kids_chair())
    w.add("bean_bag_1", (4.5, 3.75, 0, S), bean_bag("bean_orange"))
    w.add("bean_bag_2", (5.4, 3.2, 0, WEST), bean_bag("bean_purple"))
    w.add("toy_box", (1.6, T / 2 + 0.25, 0, N), toy_box())  # under window_1


def lobby(w):
    e0, e1 = MAIN_ENTRANCE
    w.add("door_1", (e0 + 0.04, 0.47, 0, WEST), base.door())  # two leaves swung open into the lobby
    w.add("door_2", (e1 - 0.04, 0.47, 0, WEST), base.door())
    w.add("exit_sign_1", ((e0 + e1) / 2, T / 2 + 0.03, 2.55, N), exit_sign())
    for i, x in enumerate((8.75, 9.5, 10.25), 1):
        w.add(f"security_gate_{i}", (x, 1.7, 0, N), security_gate())
    w.add("book_return", (7.3, T / 2, 0, N), book_return())
    w.add("notice_board", (6.45, T / 2 + 0.02, 1.5, N), notice_board())
    w.add("potted_plant_1", (8.15, 0.45, 0, N), base.plant())
    w.add("potted_plant_2", (10.85, 0.45, 0, N), base.plant())
    w.add("waste_bin_1", (11.5, 0.4, 0, N), waste_bin())
    w.add("book_display", (7.6, 2.4, 0, N), book_display())
    w.add("self_checkout", (6.85, 3.75, 0, E), self_checkout())
    # the circulation desk east of the entrance, its front to the west, the librarian behind it
    w.add("circulation_desk", (11.0, 2.3, 0, WEST), circulation_desk())
    w.add("office_chair_1", (11.62, 2.0, 0, WEST), base.office_chair())
    w.add("monitor_1", (10.98, 2.0, 0.76, E), base.monitor())
    w.add("keyboard_1", (11.22, 2.0, 0.76, E), base.keyboard())
    w.add("fire_extinguisher_1", (XST - T / 2 - 0.1, 0.6, 0, WEST), fire_extinguisher())


def staff_workroom(w):
    s0, _ = STAFF_DOOR
    w.add("door_3", (XST + 0.47, s0 + 0.04, 0, N), base.door())  # swung open into the workroom
    w.add("window_4", (15.0, T / 2 + 0.02, 1.5, N), base.window())
    w.add("work_table", (14.4, 2.6, 0, N), work_table())
    w.add("office_chair_2", (13.9, 1.85, 0, N), base.office_chair())
    w.add("office_chair_3", (14.9, 3.35, 0, S), base.office_chair())
    yd = T / 2 + 0.36
    w.add("computer_desk_1", (13.0, yd, 0, N), computer_desk())  # the staff computer
    w.add("monitor_2", (13.0, yd - 0.15, 0.745, N), base.monitor())
    w.add("keyboard_2", (13.0, yd + 0.13, 0.745, N), base.keyboard())
    w.add("office_chair_4", (13.0, yd + 0.68, 0, S), base.office_chair())
    w.add("filing_cabinet_1", (XWC - T / 2 - 0.32, 3.15, 0, WEST), base.filing_cabinet())
    w.add("filing_cabinet_2", (XWC - T / 2 - 0.32, 3.7, 0, WEST), base.filing_cabinet())
    w.add("book_cart_1", (12.6, 2.3, 0, WEST), book_cart())  # the returns, waiting to be shelved
    w.add("waste_bin_2", (15.95, 0.4, 0, N), waste_bin())


def toilets(w):
    t0, _ = TOILET_DOOR
    w.add("door_4", (t0 + 0.04, YS - 0.47, 0, WEST), base.door())  # swung open into the toilets
    w.add("toilet_1", (W - T / 2 - 0.32, 0.75, 0, WEST), toilet())
    w.add("toilet_2", (W - T / 2 - 0.32, 2.25, 0, WEST), toilet())
    for i, y in enumerate((1.0, 1.8), 1):
        w.add(f"sink_{i}", (XWC + T / 2, y, 0, E), sink())
        w.add(f"mirror_{i}", (XWC + T / 2 + 0.01, y, 1.55, E), mirror())
    w.add("hand_dryer", (XWC + T / 2 + 0.01, 2.7, 0, E), hand_dryer())
    w.add("waste_bin_3", (16.8, 3.3, 0, N), waste_bin())


def stacks(w):
    n = 1
    for k, y in enumerate((7.5, 9.3, 11.1)):  # single-sided along the west wall
        n += 1
        w.add(f"bookshelf_{n}", (T / 2 + 0.18, y, 0, E), bookshelf(1.8, 2.0, 5, False, 2 * k + 1))
    for r, x in enumerate((1.7, 3.3, 4.9, 6.5, 8.1)):  # five double-sided rows, north-south
        for k, y in enumerate((7.5, 9.3, 11.1)):
            n += 1
            w.add(f"bookshelf_{n}", (x, y, 0, WEST), bookshelf(1.8, 2.0, 5, True, 7 * r + 3 * k))
    w.add("catalog_terminal_1", (3.3, 5.9, 0, S), catalog_terminal())
    w.add("catalog_terminal_2", (6.5, 5.9, 0, S), catalog_terminal())
    w.add("step_stool_1", (2.5, 8.4, 0, N), step_stool())
    w.add("step_stool_2", (5.7, 10.9, 0, N), step_stool())
    w.add("book_cart_2", (4.1, 9.0, 0, WEST), book_cart())
    w.add("window_5", (2.5, D - T / 2 - 0.02, 1.6, S), base.window())
    w.add("window_6", (5.7, D - T / 2 - 0.02, 1.6, S), base.window())
    f0, f1 = FIRE_EXIT
    w.add("door_5", ((f0 + f1) / 2, D - 0.03, 0, S), fire_exit_door(f1 - f0))
    w.add("exit_sign_2", ((f0 + f1) / 2, D - T / 2 - 0.03, 2.45, S), exit_sign())
    w.add("fire_extinguisher_2", (8.45, D - T / 2 - 0.1, 0, S), fire_extinguisher())
    w.add("potted_plant_3", (7.5, 13.55, 0, N), base.plant())


def reading_area(w):
    n = m = 0
    for i, (cx, cy) in enumerate(((12.2, 6.0), (14.9, 6.0), (12.2, 8.6), (14.9, 8.6)), 1):
        w.add(f"reading_table_{i}", (cx, cy, 0, N), reading_table())
        for dx in (-0.5, 0.5):
            n += 1
            w.add(f"chair_{n}", (cx + dx, cy - 0.75, 0, N), chair())
            n += 1
            w.add(f"chair_{n}", (cx + dx, cy + 0.75, 0, S), chair())
            m += 1
            w.add(f"reading_lamp_{m}", (cx + dx, cy, 0.765, N), reading_lamp())
    w.add("potted_plant_4", (10.9, 5.1, 0, N), base.plant())
    return n


def computer_area(w):
    yn = D - T / 2 - 0.36
    desks = [(11.6, yn, S), (13.1, yn, S), (14.6, yn, S), (12.0, 11.0, N), (13.6, 11.0, N)]
    for i, (x, y, yaw) in enumerate(desks, 2):
        f = 1 if yaw == N else -1  # +1: the user sits north of the desk
        w.add(f"computer_desk_{i}", (x, y, 0, yaw), computer_desk())
        w.add(f"monitor_{i + 1}", (x, y - 0.15 * f, 0.745, yaw), base.monitor())
        w.add(f"keyboard_{i + 1}", (x, y + 0.13 * f, 0.745, yaw), base.keyboard())
        w.add(f"office_chair_{i + 3}", (x, y + 0.68 * f, 0, S if yaw == N else N), base.office_chair())
    w.add("photocopier", (XR - T / 2 - 0.32, 10.6, 0, WEST), photocopier())
    w.add("printer", (XR - T / 2 - 0.27, 13.4, 0, WEST), printer())
    w.add("waste_bin_4", (XR - T / 2 - 0.2, 12.8, 0, N), waste_bin())


def lounge(w):
    w.add("window_7", (W - T / 2 - 0.02, 5.6, 1.5, WEST), base.window())
    w.add("window_8", (W - T / 2 - 0.02, 7.6, 1.5, WEST), base.window())
    w.add("armchair_1", (18.6, 5.6, 0, N), armchair())
    w.add("armchair_2", (18.6, 7.3, 0, S), armchair())
    w.add("floor_lamp", (19.55, 6.45, 0, N), floor_lamp())
    w.add("magazine_rack", (17.2, YSR - T / 2 - 0.2, 0, S), magazine_rack())
    w.add("water_fountain", (19.4, YS + T / 2, 0, N), water_fountain())
    w.add("fire_extinguisher_3", (18.2, YS + T / 2 + 0.1, 0, N), fire_extinguisher())
    w.add("potted_plant_5", (19.5, 8.1, 0, N), base.plant())


def study_rooms(w, chair_n):
    for room, ((d0, _), cy) in enumerate(((STUDY_DOOR_1, 9.95), (STUDY_DOOR_2, 12.65)), 1):
        w.add(f"door_{5 + room}", (XR + 0.47, d0 + 0.04, 0, N), base.door())  # swung open into the room
        w.add(f"study_table_{room}", (18.4, cy, 0, N), study_table())
        for dx in (-0.45, 0.45):
            chair_n += 1
            w.add(f"chair_{chair_n}", (18.4 + dx, cy - 0.7, 0, N), chair())
            chair_n += 1
            w.add(f"chair_{chair_n}", (18.4 + dx, cy + 0.7, 0, S), chair())
        w.add(f"whiteboard_{room}", (W - T / 2 - 0.02, cy, 1.4, E), base.whiteboard())
    w.add("window_9", (18.4, D - T / 2 - 0.02, 1.6, S), base.window())


def main():
    w = World()
    childrens_corner(w)
    lobby(w)
    staff_workroom(w)
    toilets(w)
    stacks(w)
    chairs = reading_area(w)
    computer_area(w)
    lounge(w)
    study_rooms(w, chairs)
    z = H - 0.25
    lights = [base.point_light(name, x, y, z, "0.8 0.79 0.75")
              for name, x, y in (("light_children", 3.0, 2.3), ("light_lobby", 9.0, 2.3),
                                 ("light_staff", 14.2, 2.3), ("light_toilets", 18.2, 2.3),
                                 ("light_stacks_s", 4.5, 7.5), ("light_stacks_n", 4.5, 11.5),
                                 ("light_reading", 13.5, 7.3), ("light_computers", 13.3, 12.2),
                                 ("light_lounge", 18.2, 6.6), ("light_study_1", 18.2, 9.95),
                                 ("light_study_2", 18.2, 12.65))]
    print(base.world_sdf("semsplat_library", """The semsplat library: a public library of 20 m x 14 m on one floor (south, west to east:
     the children's corner, the entrance lobby with the circulation desk, the security gates and
     the book return, the staff workroom, the toilets; north: the stacks with the fire exit, the
     reading area, the public computers with the printer and the photocopier, the lounge with the
     magazine rack, two study rooms) for measuring on a world nobody tuned on. Generated by
     library_models/make_library.py; all models are inline.""", lights, w.out))


if __name__ == "__main__":
    main()
