#!/usr/bin/env python3
"""Writes data/worlds/grocery.world: a neighbourhood corner shop of 10 m x 8 m (the entrance in the
middle of the south shop front, the till by it on the west with the cash register and the card
terminal, the magazine rack, baskets, carts and the cash machine by the door; three aisles of
grocery shelves in the middle; the chilled section in the north-west: drinks fridges on the west
wall, ice cream freezers on the north wall; fruit and the scale, the bread rack on the east side;
the stock room behind a partition in the north-east with a pallet of boxes, a pallet jack, a hand
truck and the mop bucket) for measuring the semantic stack on a world nobody tuned on. Every model
is inline (boxes, cylinders, spheres), so the world needs no model path. Model names are what a
world author would type; the class is the name less its _<number> (no "retail_" prefix: synth drops
it as a model-pack vendor token). The primitives and the SDF writing are the office generator's.
Run: python3 data/worlds/grocery_models/make_grocery.py > data/worlds/grocery.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document)
from make_ward import turned, wheel, castors  # noqa: E402  (rotated visuals, wheels, castors)

W, D, H = 10.0, 8.0, 3.0   # shop width (x), depth (y), wall height
T = 0.1                    # wall thickness
EX0, EX1 = 4.2, 5.1        # the entrance in the south wall
SX, SY = 6.5, 6.2          # the stock room: x > SX, y > SY
DX0, DX1 = 7.2, 8.1        # the stock room's doorway in its south partition

base.COL.update({
    "tiles": "0.82 0.8 0.76", "steel": "0.75 0.77 0.79", "shelf_white": "0.93 0.93 0.9",
    "pack_red": "0.8 0.2 0.15", "pack_yellow": "0.92 0.78 0.2", "pack_blue": "0.2 0.4 0.75",
    "pack_green": "0.3 0.6 0.3", "pack_orange": "0.9 0.5 0.15", "fridge_red": "0.7 0.1 0.1",
    "bottle_brown": "0.45 0.25 0.1", "bottle_green": "0.2 0.55 0.3", "freezer_white": "0.95 0.96 0.97",
    "counter_top": "0.3 0.3 0.32", "counter_front": "0.55 0.35 0.2", "screen": "0.1 0.15 0.2",
    "basket_red": "0.85 0.12 0.1", "chrome": "0.8 0.82 0.85", "rubber": "0.1 0.1 0.1",
    "atm_grey": "0.45 0.48 0.52", "crate": "0.65 0.48 0.3", "apple": "0.8 0.15 0.12",
    "orange": "0.95 0.55 0.1", "banana": "0.95 0.85 0.3", "bread": "0.8 0.6 0.35",
    "pallet_wood": "0.72 0.58 0.38", "cardboard": "0.7 0.55 0.35", "jack_orange": "0.9 0.45 0.1",
    "mop_yellow": "0.95 0.8 0.15", "mop_head": "0.85 0.85 0.8", "magazine": "0.7 0.3 0.5",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
PACKS = ("pack_red", "pack_yellow", "pack_blue", "pack_green", "pack_orange")


# ---- the things (local frames: x right, y forward = the side a shopper faces, z up) ----
def grocery_shelf(length=1.2, depth=0.9, height=1.8):
    """A double-sided gondola: a back panel down the middle, four shelves on each side, packets."""
    v = [box("plinth", "shelf_white", 0, 0, 0.06, length, depth, 0.12),
         box("back", "shelf_white", 0, 0, height / 2, length, 0.04, height)]
    for side in (-1, 1):
        for i in range(4):
            z = 0.12 + 0.42 * i
            y = side * depth / 4
            v.append(box(f"shelf{side}_{i}", "steel", 0, y, z, length, depth / 2 - 0.04, 0.02))
            v += [box(f"pack{side}_{i}_{k}", PACKS[(i + k + side) % 5], -0.45 + 0.3 * k, y, z + 0.14,
                      0.22, 0.3, 0.26) for k in range(4)]
    return v


def drinks_fridge():
    """An upright glass-door fridge; the door is at +y, bottles behind it."""
    v = [box("cabinet", "fridge_red", 0, 0, 1.0, 0.8, 0.7, 2.0),
         box("header", "white", 0, 0.33, 1.9, 0.78, 0.05, 0.16),
         box("door", "glass", 0, 0.352, 1.0, 0.72, 0.01, 1.6),
         box("handle", "chrome", 0.32, 0.37, 1.0, 0.03, 0.03, 0.5)]
    for i in range(4):
        z = 0.35 + 0.4 * i
        v += [cyl(f"bottle{i}_{k}", "bottle_brown" if (i + k) % 2 else "bottle_green",
                  -0.27 + 0.18 * k, 0.2, z, 0.035, 0.26) for k in range(4)]
    return v


def ice_cream_freezer():
    """A chest freezer with a sliding glass lid, tubs inside."""
    v = [box("body", "freezer_white", 0, 0, 0.42, 1.3, 0.7, 0.84),
         box("lid", "glass", 0, 0, 0.85, 1.26, 0.66, 0.02),
         box("rim", "steel", 0, 0, 0.845, 1.32, 0.72, 0.01),
         box("plinth", "dark_metal", 0, 0, 0.02, 1.26, 0.66, 0.04)]
    return v + [cyl(f"tub{k}", PACKS[k % 5], -0.45 + 0.3 * k, 0, 0.78, 0.1, 0.1) for k in range(4)]


def checkout_counter(length=1.8, depth=0.6):
    """The till counter; customers stand at +y, the cashier at -y."""
    return [box("front", "counter_front", 0, depth / 2 - 0.03, 0.46, length, 0.06, 0.92),
            box("top", "counter_top", 0, 0, 0.94, length + 0.05, depth + 0.05, 0.04),
            box("side_l", "counter_front", -length / 2, 0, 0.46, 0.04, depth, 0.92),
            box("side_r", "counter_front", length / 2, 0, 0.46, 0.04, depth, 0.92),
            box("belt", "rubber", 0.4, 0.02, 0.965, 0.8, 0.4, 0.01)]


def cash_register():
    return [box("drawer", "grey_plastic", 0, 0, 0.05, 0.4, 0.4, 0.1),
            box("keys", "dark_metal", 0, 0.05, 0.13, 0.3, 0.2, 0.06),
            box("display", "screen", 0, -0.12, 0.25, 0.26, 0.03, 0.18),
            box("neck", "dark_metal", 0, -0.12, 0.13, 0.04, 0.04, 0.06)]


def card_terminal():
    return [box("body", "black", 0, 0, 0.03, 0.08, 0.16, 0.06),
            box("screen", "screen", 0, 0.03, 0.062, 0.06, 0.06, 0.004),
            box("stand", "dark_metal", 0, 0, -0.01, 0.1, 0.1, 0.02)]


def stool():
    return [cyl("seat", "black", 0, 0, 0.72, 0.18, 0.06),
            cyl("pole", "chrome", 0, 0, 0.36, 0.025, 0.7),
            cyl("foot_ring", "chrome", 0, 0, 0.28, 0.16, 0.02),
            cyl("base", "chrome", 0, 0, 0.02, 0.22, 0.04)]


def security_camera():
    """Hangs from the ceiling: the mount at the top (local z 0 is the ceiling), the lens at +y."""
    return [cyl("mount", "white", 0, 0, -0.05, 0.04, 0.1),
            turned(cyl("body", "white", 0, 0.08, -0.14, 0.05, 0.22), "1.2 0 0"),
            turned(cyl("lens", "black", 0, 0.19, -0.19, 0.03, 0.02), "1.2 0 0")]


def magazine_rack():
    """Three sloping tiers of magazines facing +y, against a wall behind (-y)."""
    v = [box("back", "dark_metal", 0, -0.18, 0.65, 0.9, 0.03, 1.3)]
    for i in range(3):
        z = 0.35 + 0.35 * i
        y = 0.1 - 0.08 * i
        v += [turned(box(f"tier{i}", "dark_metal", 0, y, z, 0.9, 0.2, 0.02), "-0.3 0 0"),
              turned(box(f"mags{i}", "magazine" if i % 2 else "pack_blue", 0, y - 0.02, z + 0.13,
                         0.84, 0.02, 0.26), "-0.3 0 0")]
    return v + [box("foot", "dark_metal", 0, 0, 0.02, 0.9, 0.4, 0.04)]


def shopping_basket(z0=0.0):
    """One plastic basket with its two handles."""
    return [box("bottom", "basket_red", 0, 0, z0 + 0.01, 0.42, 0.3, 0.02),
            box("side_f", "basket_red", 0, 0.145, z0 + 0.11, 0.44, 0.01, 0.2),
            box("side_b", "basket_red", 0, -0.145, z0 + 0.11, 0.44, 0.01, 0.2),
            box("side_l", "basket_red", -0.215, 0, z0 + 0.11, 0.01, 0.3, 0.2),
            box("side_r", "basket_red", 0.215, 0, z0 + 0.11, 0.01, 0.3, 0.2),
            box("handle", "black", 0, 0, z0 + 0.26, 0.02, 0.3, 0.02)]


def shopping_cart():
    """A wire cart: the basket at the front (+y), the push handle at the back."""
    v = [box("basket_floor", "chrome", 0, 0.1, 0.45, 0.5, 0.8, 0.02),
         box("basket_l", "chrome", -0.25, 0.1, 0.65, 0.01, 0.8, 0.4),
         box("basket_r", "chrome", 0.25, 0.1, 0.65, 0.01, 0.8, 0.4),
         box("basket_front", "chrome", 0, 0.5, 0.65, 0.5, 0.01, 0.4),
         box("basket_back", "chrome", 0, -0.3, 0.65, 0.5, 0.01, 0.4),
         box("handle", "basket_red", 0, -0.38, 1.0, 0.52, 0.04, 0.04),
         box("frame_l", "chrome", -0.2, 0, 0.22, 0.02, 0.8, 0.02),
         box("frame_r", "chrome", 0.2, 0, 0.22, 0.02, 0.8, 0.02)]
    return v + castors(0.2, 0.35, 0.05)


def atm():
    """A free-standing cash machine; the screen and keypad at +y."""
    return [box("body", "atm_grey", 0, 0, 0.8, 0.7, 0.6, 1.6),
            box("hood", "dark_metal", 0, 0.28, 1.45, 0.6, 0.1, 0.12),
            box("screen", "screen", 0, 0.302, 1.2, 0.36, 0.005, 0.26),
            box("keypad", "black", 0, 0.32, 0.95, 0.24, 0.06, 0.12),
            box("slot", "black", 0.18, 0.302, 1.05, 0.12, 0.005, 0.02)]


def fruit_stand():
    """A table of sloping crates of apples, oranges and bananas, facing +y."""
    v = [box("table", "wood", 0, 0, 0.62, 1.6, 0.9, 0.04)] + legs("wood", 0.75, 0.4, 0.6, 0.05)
    for k, fruit in enumerate(("apple", "orange", "banana")):
        x = -0.52 + 0.52 * k
        v.append(turned(box(f"crate{k}", "crate", x, 0, 0.72, 0.48, 0.8, 0.16), "0.25 0 0"))
        v += [sph(f"{fruit}{j}", fruit, x - 0.12 + 0.12 * (j % 3), -0.2 + 0.2 * (j // 3),
                  0.8 + 0.05 * (j // 3), 0.05) for j in range(6)]
    return v


def weighing_scale():
    """A produce scale on a post: the pan on top, the dial facing +y."""
    return [cyl("base", "dark_metal", 0, 0, 0.02, 0.2, 0.04),
            cyl("post", "steel", 0, 0, 0.5, 0.03, 0.96),
            box("head", "white", 0, 0, 1.05, 0.3, 0.22, 0.14),
            box("dial", "screen", 0, 0.112, 1.05, 0.18, 0.005, 0.08),
            cyl("pan", "steel", 0, 0, 1.14, 0.16, 0.02)]


def bread_rack():
    """Wooden rack with four sloping shelves of loaves, facing +y, its back to a wall."""
    v = [box("side_l", "wood", -0.58, 0, 0.8, 0.04, 0.45, 1.6),
         box("side_r", "wood", 0.58, 0, 0.8, 0.04, 0.45, 1.6),
         box("back", "light_wood", 0, -0.21, 0.8, 1.16, 0.02, 1.6)]
    for i in range(4):
        z = 0.25 + 0.38 * i
        v.append(turned(box(f"shelf{i}", "light_wood", 0, 0, z, 1.12, 0.42, 0.02), "0.2 0 0"))
        v += [box(f"loaf{i}_{k}", "bread", -0.4 + 0.27 * k, 0.02, z + 0.07, 0.2, 0.3, 0.11)
              for k in range(4)]
    return v


def pallet():
    v = [box(f"top{i}", "pallet_wood", 0, -0.36 + 0.18 * i, 0.13, 1.2, 0.12, 0.02) for i in range(5)]
    v += [box(f"block{i}", "pallet_wood", -0.55 + 0.55 * (i % 3), -0.34 + 0.68 * (i // 3), 0.065,
              0.1, 0.12, 0.11) for i in range(6)]
    return v + [box(f"runner{i}", "pallet_wood", 0, -0.34 + 0.68 * i, 0.01, 1.2, 0.12, 0.02) for i in range(2)]


def cardboard_box(sx=0.5, sy=0.4, sz=0.4):
    return [box("body", "cardboard", 0, 0, sz / 2, sx, sy, sz),
            box("tape", "pack_yellow", 0, 0, sz + 0.002, 0.06, sy + 0.002, 0.004)]


def pallet_jack():
    """Two forks at +y, the wheel housing and the tiller handle at the back."""
    v = [box("fork_l", "jack_orange", -0.2, 0.45, 0.05, 0.16, 1.1, 0.06),
         box("fork_r", "jack_orange", 0.2, 0.45, 0.05, 0.16, 1.1, 0.06),
         box("housing", "jack_orange", 0, -0.18, 0.2, 0.56, 0.2, 0.34),
         turned(box("tiller", "dark_metal", 0, -0.35, 0.75, 0.04, 0.04, 1.1), "-0.3 0 0"),
         box("grip", "black", 0, -0.52, 1.28, 0.3, 0.04, 0.04)]
    return v + [wheel("wheel_l", "rubber", -0.12, -0.18, 0.08, 0.08, 0.05),
                wheel("wheel_r", "rubber", 0.12, -0.18, 0.08, 0.08, 0.05)]


def hand_truck():
    """An upright sack truck: the nose plate at +y, two wheels at the back."""
    return [box("rail_l", "dark_metal", -0.18, 0, 0.65, 0.03, 0.03, 1.2),
            box("rail_r", "dark_metal", 0.18, 0, 0.65, 0.03, 0.03, 1.2),
            box("cross0", "dark_metal", 0, 0, 0.5, 0.36, 0.02, 0.02),
            box("cross1", "dark_metal", 0, 0, 0.9, 0.36, 0.02, 0.02),
            box("nose", "steel", 0, 0.12, 0.03, 0.4, 0.24, 0.01),
            box("grip", "black", 0, 0, 1.24, 0.4, 0.04, 0.03),
            wheel("wheel_l", "rubber", -0.24, -0.08, 0.12, 0.12, 0.06),
            wheel("wheel_r", "rubber", 0.24, -0.08, 0.12, 0.12, 0.06)]


def mop_bucket():
    return [box("bucket", "mop_yellow", 0, 0, 0.22, 0.5, 0.35, 0.34),
            box("wringer", "mop_yellow", 0.12, 0, 0.45, 0.2, 0.3, 0.12),
            turned(cyl("mop_handle", "light_wood", 0.05, -0.05, 0.85, 0.014, 1.3), "0.12 0 0"),
            cyl("mop_head", "mop_head", 0, 0, 0.3, 0.1, 0.2)] + castors(0.2, 0.13, 0.03)


def walls():
    """The shop front with the entrance, the stock room partitioned off in the north-east corner."""
    return base.corner_room_walls(W, D, H, (EX0, EX1), (SX, SY), (DX0, DX1), T)


def main():
    out = base.shell(walls(), "floor_shop", "tiles", W, D, H)
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # the shop front: the entrance (door swung open against the wall), two windows
    add("door_1", (EX0 + 0.04, 0.47, 0, 1.5708), base.door())
    add("window_1", (2.0, T / 2 + 0.02, 1.6, 0), base.window())
    add("window_2", (8.6, T / 2 + 0.02, 1.6, 0), base.window())
    # the till (south-west): the counter along y, customers on its east side, the cashier's
    # stool on the west; the register and card terminal on the counter
    add("checkout_counter", (1.6, 1.9, 0, -1.5708), checkout_counter())
    add("cash_register", (1.55, 2.3, 0.96, -1.5708), cash_register())
    add("card_terminal", (1.75, 1.5, 0.97, -1.5708), card_terminal())
    add("stool", (0.75, 2.0, 0, 0), stool())
    add("security_camera", (0.35, 0.35, H, -0.785), security_camera())  # looks at the till
    add("magazine_rack", (3.2, T / 2 + 0.22, 0, 0), magazine_rack())
    # by the entrance: baskets stacked on the west, carts and the cash machine on the east
    add("shopping_basket_1", (3.75, 0.95, 0, 0), shopping_basket(0.0))
    add("shopping_basket_2", (3.75, 0.95, 0, 0), shopping_basket(0.12))
    add("shopping_basket_3", (3.75, 0.95, 0, 0), shopping_basket(0.24))
    add("shopping_cart_1", (5.8, 0.75, 0, 3.1416), shopping_cart())
    add("shopping_cart_2", (6.4, 0.75, 0, 3.1416), shopping_cart())
    add("atm", (7.35, T / 2 + 0.32, 0, 0), atm())
    # three aisles of grocery shelves running north-south, two gondolas in each
    for i, (x, y) in enumerate(((3.0, 3.5), (3.0, 4.75), (4.9, 3.5), (4.9, 4.75), (6.8, 3.5),
                                (6.8, 4.75)), 1):
        add(f"grocery_shelf_{i}", (x, y, 0, 1.5708), grocery_shelf())
    # the chilled section (north-west): drinks fridges on the west wall facing east, ice cream
    # freezers along the north wall
    for i, y in enumerate((4.0, 4.85, 5.7), 1):
        add(f"drinks_fridge_{i}", (T / 2 + 0.37, y, 0, -1.5708), drinks_fridge())
    add("ice_cream_freezer_1", (1.9, D - T / 2 - 0.4, 0, 3.1416), ice_cream_freezer())
    add("ice_cream_freezer_2", (3.35, D - T / 2 - 0.4, 0, 3.1416), ice_cream_freezer())
    # fruit and bread on the east side: the fruit stand with its scale, the bread rack on the wall
    add("fruit_stand", (8.6, 2.0, 0, 3.1416), fruit_stand())
    add("weighing_scale", (9.6, 1.0, 0, 1.5708), weighing_scale())
    add("bread_rack", (W - T / 2 - 0.25, 4.2, 0, 1.5708), bread_rack())
    # the stock room (north-east), its door hinged at x 7.2 and swung open into the room
    add("door_2", (DX0 + 0.04, SY + 0.47, 0, 1.5708), base.door())
    add("window_3", (W - T / 2 - 0.02, 7.1, 1.6, 1.5708), base.window())
    add("pallet", (9.2, 7.3, 0, 0), pallet())
    for i, (x, y, z) in enumerate(((8.92, 7.1, 0.14), (9.48, 7.1, 0.14), (8.92, 7.5, 0.14),
                                   (9.2, 7.3, 0.54)), 1):
        add(f"cardboard_box_{i}", (x, y, z, 0), cardboard_box())
    add("cardboard_box_5", (8.3, 6.55, 0, 0.3), cardboard_box(0.6, 0.45, 0.5))
    add("pallet_jack", (7.3, 7.6, 0, -1.5708), pallet_jack())
    add("hand_truck", (9.65, 6.6, 0, 1.5708), hand_truck())
    add("mop_bucket", (6.85, 7.0, 0, 0), mop_bucket())
    lights = [base.point_light(name, x, y, 2.75, "0.78 0.78 0.75")
              for name, x, y in (("light_till", 2.0, 1.8), ("light_aisles", 4.9, 3.9),
                                 ("light_chilled", 2.2, 6.0), ("light_produce", 8.4, 2.8),
                                 ("light_stock", 8.3, 7.1))]
    print(base.world_sdf("semsplat_grocery", """The semsplat grocery: a corner shop of 10 m x 8 m (the till, magazines, baskets, carts
     and the cash machine by the entrance in the south; three aisles of grocery shelves; drinks
     fridges and ice cream freezers in the north-west; fruit, the scale and bread in the east; the
     stock room in the north-east) for measuring on a world nobody tuned on. Generated by
     grocery_models/make_grocery.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
