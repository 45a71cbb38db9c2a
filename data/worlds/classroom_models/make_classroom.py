#!/usr/bin/env python3
"""Writes data/worlds/classroom.world: a primary-school classroom of 9 m x 7 m (eight student desks
in two rows facing the whiteboard on the north wall; the teacher's area in the north-east with the
teacher's desk and chair, a laptop and a globe on the desk, the supply cabinet; a reading corner in
the south-west with two bookshelves, a rug and bean bags; the fish tank and an easel on the west
wall; windows with radiators under them on the east wall; the door, a coat rack and the bulletin
board on the south wall) for measuring the semantic stack on a world nobody tuned on. Every model
is inline (boxes, cylinders, spheres), so the world needs no model path. Model names are what a
world author would type; the class is the name less its _<number>. The primitives and the SDF
writing are the office generator's.
Run: python3 data/worlds/classroom_models/make_classroom.py > data/worlds/classroom.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document)

W, D, H = 9.0, 7.0, 3.0    # room width (x), depth (y), wall height
T = 0.1                    # wall thickness
DOOR_X0, DOOR_X1 = 7.4, 8.3  # the entrance in the south wall

base.COL.update({
    "lino": "0.7 0.66 0.55", "desk_top": "0.86 0.78 0.6", "chair_red": "0.8 0.25 0.2",
    "chair_blue": "0.2 0.4 0.75", "cork": "0.7 0.52 0.32", "paper_yellow": "0.95 0.88 0.4",
    "paper_pink": "0.95 0.6 0.7", "rug_green": "0.35 0.6 0.4", "bean_orange": "0.95 0.55 0.2",
    "bean_purple": "0.5 0.3 0.65", "ocean": "0.2 0.45 0.8", "land": "0.4 0.65 0.3",
    "brass": "0.75 0.6 0.25", "aqua": "0.45 0.75 0.85", "gravel": "0.55 0.5 0.45",
    "radiator_white": "0.93 0.93 0.9", "cabinet_grey": "0.62 0.64 0.66", "canvas": "0.98 0.97 0.92",
    "book_red": "0.7 0.15 0.15", "book_blue": "0.15 0.3 0.6", "book_green": "0.2 0.5 0.25",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned = base.turned


# ---- the things (local frames: x right, y forward = away from the user, z up) ----
def student_desk():
    return [box("top", "desk_top", 0, 0, 0.64, 0.65, 0.5, 0.03),
            box("tray", "dark_metal", 0, -0.02, 0.54, 0.6, 0.4, 0.02)] + legs("metal", 0.29, 0.21, 0.63, 0.03)


def student_chair(c):
    # a small plastic shell chair; the back at -y, the sitter faces +y
    return [box("seat", c, 0, 0, 0.37, 0.36, 0.35, 0.03),
            box("back", c, 0, -0.17, 0.57, 0.36, 0.03, 0.34)] + legs("metal", 0.16, 0.15, 0.36, 0.025)


def teacher_desk():
    # a desk with a drawer pedestal on the right, the teacher sits at -y
    return [box("top", "wood", 0, 0, 0.75, 1.4, 0.7, 0.04),
            box("pedestal", "wood", 0.5, 0, 0.37, 0.38, 0.66, 0.73),
            box("modesty", "wood", -0.2, 0.33, 0.45, 0.95, 0.02, 0.5)] + \
        [box(f"leg{i}", "wood", -0.66, s * 0.31, 0.365, 0.05, 0.05, 0.73) for i, s in enumerate((-1, 1))]


def laptop():
    # open, the screen at +y (away from the user); sits on a desk top (pose z = top)
    return [box("base", "dark_metal", 0, 0, 0.01, 0.34, 0.24, 0.02),
            box("lid", "dark_metal", 0, 0.12, 0.12, 0.34, 0.015, 0.22),
            box("screen", "glass", 0, 0.11, 0.12, 0.3, 0.004, 0.19)]


def globe():
    # a tilted earth on a stand (pose z = the desk top)
    return [cyl("foot", "brass", 0, 0, 0.01, 0.08, 0.02),
            cyl("post", "brass", 0, 0, 0.08, 0.01, 0.14),
            sph("earth", "ocean", 0, 0, 0.3, 0.15),
            sph("continent", "land", 0.06, -0.07, 0.34, 0.09),
            turned(cyl("axis", "brass", 0, 0, 0.3, 0.006, 0.36), "0.41 0 0")]


def whiteboard():
    # a wide board on the wall behind it (+y), the marker tray at its foot
    return [box("frame", "metal", 0, 0, 0, 2.6, 0.03, 1.2),
            box("board", "white", 0, -0.016, 0, 2.5, 0.004, 1.1),
            box("tray", "metal", 0, -0.04, -0.6, 2.2, 0.06, 0.02)]


def bulletin_board():
    # cork with pinned sheets; the wall behind it at -y
    return [box("frame", "wood", 0, 0, 0, 1.8, 0.03, 1.0),
            box("cork", "cork", 0, 0.016, 0, 1.7, 0.004, 0.9),
            box("sheet1", "white", -0.5, 0.02, 0.15, 0.21, 0.003, 0.3),
            box("sheet2", "paper_yellow", 0.05, 0.02, -0.1, 0.3, 0.003, 0.21),
            box("sheet3", "paper_pink", 0.55, 0.02, 0.2, 0.21, 0.003, 0.3)]


def bookshelf():
    # a low open bookcase for children, back at -y, books on three shelves
    v = [box("back", "light_wood", 0, -0.14, 0.6, 1.0, 0.02, 1.2),
         box("side_l", "light_wood", -0.49, 0, 0.6, 0.02, 0.3, 1.2),
         box("side_r", "light_wood", 0.49, 0, 0.6, 0.02, 0.3, 1.2)]
    v += [box(f"shelf{i}", "light_wood", 0, 0, 0.02 + 0.39 * i, 0.96, 0.3, 0.02) for i in range(4)]
    books = ("book_red", "book_blue", "book_green")
    v += [box(f"books{i}", books[i], -0.1 + 0.1 * i, 0, 0.17 + 0.39 * i, 0.7, 0.2, 0.26) for i in range(3)]
    return v


def rug():
    return [box("pile", "rug_green", 0, 0, 0.006, 2.4, 2.0, 0.012),
            box("border", "paper_yellow", 0, 0, 0.004, 2.5, 2.1, 0.008)]


def bean_bag(c):
    return [sph("body", c, 0, 0, 0.25, 0.38), sph("top", c, 0, -0.1, 0.45, 0.25)]


def supply_cabinet():
    # a tall two-door steel cupboard, doors at +y
    return [box("body", "cabinet_grey", 0, 0, 0.95, 0.9, 0.45, 1.9),
            box("seam", "dark_metal", 0, 0.226, 0.95, 0.01, 0.005, 1.8),
            box("handle_l", "metal", -0.06, 0.235, 1.0, 0.02, 0.02, 0.15),
            box("handle_r", "metal", 0.06, 0.235, 1.0, 0.02, 0.02, 0.15)]


def projector():
    # ceiling-mounted: a drop pole from the ceiling (pose z = the ceiling), the lens at +y
    return [cyl("pole", "metal", 0, 0, -0.2, 0.02, 0.4),
            box("body", "white", 0, 0, -0.45, 0.34, 0.28, 0.12),
            turned(cyl("lens", "black", 0, 0.15, -0.45, 0.04, 0.04), "1.5708 0 0")]


def coat_rack():
    # a row of pegs on a board along the wall behind it (-y)
    v = [box("board", "wood", 0, 0, 1.45, 1.6, 0.03, 0.14)]
    return v + [turned(cyl(f"peg{i}", "brass", -0.7 + 0.2 * i, 0.06, 1.45, 0.012, 0.1), "1.5708 0 0")
                for i in range(8)]


def trash_can():
    return [cyl("body", "chair_blue", 0, 0, 0.22, 0.15, 0.44)]


def easel():
    # an A-frame with a paper pad facing -y
    return [box("leg_l", "light_wood", -0.3, 0, 0.75, 0.04, 0.04, 1.5),
            box("leg_r", "light_wood", 0.3, 0, 0.75, 0.04, 0.04, 1.5),
            turned(box("leg_back", "light_wood", 0, 0.25, 0.7, 0.04, 0.04, 1.45), "-0.35 0 0"),
            box("ledge", "light_wood", 0, -0.04, 0.75, 0.7, 0.08, 0.03),
            box("pad", "canvas", 0, -0.03, 1.1, 0.6, 0.01, 0.7)]


def fish_tank():
    # a glass tank of water on its own cabinet stand, glass front at -y
    return [box("stand", "wood", 0, 0, 0.4, 0.9, 0.4, 0.8),
            box("water", "aqua", 0, 0, 1.0, 0.86, 0.36, 0.4),
            box("gravel", "gravel", 0, 0, 0.82, 0.86, 0.36, 0.04),
            box("lid", "black", 0, 0, 1.24, 0.9, 0.4, 0.03)]


def radiator():
    # a panel radiator: fins in front of a back plate, the wall behind it (+y)
    v = [box("plate", "radiator_white", 0, 0.02, 0.45, 1.0, 0.02, 0.55)]
    return v + [box(f"fin{i}", "radiator_white", -0.45 + 0.1 * i, -0.02, 0.45, 0.05, 0.06, 0.55)
                for i in range(10)]


def walls():
    v, wall = base.wall_builder(H, T)
    # outer walls; the entrance (x 7.4..8.3) in the south wall
    wall(0, 0, DOOR_X0, 0); wall(DOOR_X1, 0, W, 0); wall(DOOR_X0, 0, DOOR_X1, 0, 2.1, H)
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    return v


def main():
    out = base.shell(walls(), "floor_classroom", "lino", W, D, H)
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # the pupils: two rows of four desks facing the whiteboard (north), a chair behind each desk
    n = 0
    for row, y in enumerate((4.3, 2.9)):
        for x in (2.6, 3.9, 5.2, 6.5):
            n += 1
            add(f"student_desk_{n}", (x, y, 0, 0), student_desk())
            add(f"student_chair_{n}", (x, y - 0.42, 0, 0), student_chair(("chair_red", "chair_blue")[n % 2]))
    # the front: the whiteboard, the teacher's area in the north-east
    add("whiteboard", (4.2, D - T / 2 - 0.02, 1.45, 0), whiteboard())
    add("teacher_desk", (6.9, 5.75, 0, 3.1416), teacher_desk())   # faces the class
    add("teacher_chair", (6.9, 6.35, 0, 3.1416), base.office_chair())  # a swivel chair
    add("laptop", (6.75, 5.8, 0.77, 3.1416), laptop())
    add("globe", (7.35, 5.6, 0.77, 0), globe())
    add("supply_cabinet", (8.45, D - T / 2 - 0.23, 0, 3.1416), supply_cabinet())
    add("trash_can_1", (8.0, 5.35, 0, 0), trash_can())
    add("wall_clock", (6.9, D - T / 2 - 0.02, 2.45, 0), base.wall_clock())
    add("projector", (4.2, 3.4, H, 0), projector())
    # the west wall: the easel in the north-west corner, the fish tank
    add("easel", (0.8, 6.2, 0, 2.4), easel())
    add("fish_tank", (T / 2 + 0.21, 4.3, 0, -1.5708), fish_tank())
    # the reading corner in the south-west: bookshelves on both walls, a rug with bean bags
    add("bookshelf_1", (T / 2 + 0.16, 1.6, 0, -1.5708), bookshelf())
    add("bookshelf_2", (1.9, T / 2 + 0.16, 0, 0), bookshelf())
    add("rug", (1.55, 1.45, 0, 0), rug())
    add("bean_bag_1", (1.0, 1.05, 0, 0.6), bean_bag("bean_orange"))
    add("bean_bag_2", (2.15, 1.3, 0, -0.4), bean_bag("bean_purple"))
    add("bean_bag_3", (1.2, 2.1, 0, 2.2), bean_bag("chair_red"))
    # the east wall: two windows, a radiator under each
    for i, y in enumerate((2.2, 4.6), 1):
        add(f"window_{i}", (W - T / 2 - 0.02, y, 1.65, 1.5708), base.window())
        add(f"radiator_{i}", (W - T / 2 - 0.05, y, 0, 1.5708), radiator())
    # the south wall: the bulletin board, the coat rack by the door, the door swung open
    add("bulletin_board", (4.3, T / 2 + 0.02, 1.5, 0), bulletin_board())
    add("coat_rack", (6.4, T / 2 + 0.02, 0, 0), coat_rack())
    add("trash_can_2", (8.65, 0.35, 0, 0), trash_can())
    add("door", (DOOR_X0 + 0.02, T / 2 + 0.45, 0, 1.5708), base.door())  # hinged at x 7.4
    lights = [base.point_light(name, x, y, 2.75, "0.75 0.75 0.73")
              for name, x, y in (("light_front_w", 2.5, 5.3), ("light_front_e", 6.5, 5.3),
                                 ("light_back_w", 2.5, 1.8), ("light_back_e", 6.5, 1.8))]
    print(base.world_sdf("semsplat_classroom", """The semsplat classroom: a primary-school classroom of 9 m x 7 m (eight student
     desks facing the whiteboard; the teacher's area in the north-east; a reading corner with
     bookshelves, a rug and bean bags in the south-west; the fish tank and an easel on the west
     wall; windows and radiators on the east wall; the door, coat rack and bulletin board on the
     south wall) for measuring on a world nobody tuned on. Generated by
     classroom_models/make_classroom.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
