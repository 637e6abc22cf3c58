"""The contact forces in a stack of three boxes at rest: each carries the weight above it.

Boxes of 1 m and 3, 2 and 1 kg from the bottom up rest on the ground. At rest, the impulses the
contact solver gives a contact over a step, divided by the step, are the force it carries
(Space.contact_points): the ground holds up all three boxes (6 kg · g = 58.86 N), the contact
above it the two upper ones (3 kg · g) and the top contact the last (1 kg · g). The script checks
the three forces against those weights at every step and draws them over time.

    PYTHONPATH=build/python python3 examples/python/contact_forces.py [--out forces.png]
"""
import gamephysics as gp
from _figure import close_figure, open_figure

G = 9.81  # m/s²
MASSES = (3.0, 2.0, 1.0)  # kg, from the bottom up: boxes of 1 m², density in kg/m²
DT = 1 / 60  # s


def stack():
    """A space with the ground and the three boxes, and the ids of the ground and of the boxes
    from the bottom up."""
    space = gp.Space(gp.Settings(gravity=(0.0, -G)))
    ground = space.add_body(gp.BodyDef("ground", type=gp.BodyType.static,
                                       shapes=[gp.ShapeDef(gp.Shape.segment((-5, 0), (5, 0)))]))
    boxes = [space.add_body(gp.BodyDef(
        f"box{k}", position=(0.0, 0.5 + k),
        shapes=[gp.ShapeDef(gp.Shape.box(1.0, 1.0), density=mass)]))
        for k, mass in enumerate(MASSES)]
    return space, ground, boxes


def force(space, below, above):
    """The force [N] the contact between bodies `below` and `above` carried over the last step."""
    return sum(p.normal_impulse for p in space.contact_points()
               if {p.body_a, p.body_b} == {below, above}) / DT


def main():
    args, figure, axes = open_figure(__doc__)
    space, ground, boxes = stack()
    pairs = list(zip([ground] + boxes[:-1], boxes))  # each box and what it rests on
    carried = [G * sum(MASSES[k:]) for k in range(len(MASSES))]  # N, the weight above each
    t, series = [], [[] for _ in pairs]
    for _ in range(120):
        space.step(DT)
        t.append(space.time)
        for k, (below, above) in enumerate(pairs):
            series[k].append(force(space, below, above))
    for k, name in enumerate(("ground and box0", "box0 and box1", "box1 and box2")):
        worst = max(abs(f / carried[k] - 1) for f in series[k])
        print(f"{name}: {series[k][-1]:.6f} N (the weight above, {carried[k]:.6f} N; "
              f"largest relative difference over the run {worst:.1e})")
        # The exact solve of a resting island holds to its compliance, 1e-10 of each force.
        assert worst < 1e-9, (name, worst)
        axes.plot(t, series[k], label=f"{name}: {carried[k]:.2f} N carried")
    axes.set_ylim(0.0, 1.25 * carried[0])  # room for the legend above the lines
    close_figure(args, figure, axes, "t [s]", "contact force [N]",
                 "A stack at rest: each contact carries the weight above it")


if __name__ == "__main__":
    main()
