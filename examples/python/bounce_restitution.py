"""A ball dropped from 10 m onto the ground, for three coefficients of restitution C_R.

Each bounce leaves at C_R times the impact speed (IM:col2D, DD:coeffRestitution), so the first
rebound tops out at 0.5 + C_R² · 9.5 m (the centre of a ball of radius 0.5 m): the script checks
that against the run and draws the three heights over time.

    PYTHONPATH=build/python python3 examples/python/bounce_restitution.py [--out bounce.png]
"""
import gamephysics as gp
from _figure import close_figure, open_figure

G = 9.81  # m/s²
DROP = 10.0  # m, the centre's height at t = 0
RADIUS = 0.5  # m


def heights(restitution, duration=6.0, dt=1 / 240):
    """t [s] and the ball's y [m] at every step."""
    space = gp.Space(gp.Settings(gravity=(0.0, -G)))
    ground = gp.ShapeDef(gp.Shape.segment((-10, 0), (10, 0)), restitution=restitution)
    space.add_body(gp.BodyDef("ground", type=gp.BodyType.static, shapes=[ground]))
    ball = space.add_body(gp.BodyDef(
        "ball", position=(0.0, DROP),
        shapes=[gp.ShapeDef(gp.Shape.circle(RADIUS), restitution=restitution)]))
    t, y = [0.0], [DROP]
    while space.time < duration - 1e-12:
        space.step(dt)
        t.append(space.time)
        y.append(space.state(ball).position[1])
    return t, y


def main():
    args, figure, axes = open_figure(__doc__)
    t_impact = (2 * (DROP - RADIUS) / G) ** 0.5
    for restitution in (0.5, 0.8, 1.0):
        t, y = heights(restitution)
        apex = max(yk for tk, yk in zip(t, y) if t_impact < tk < 2.5 * t_impact)
        expected = RADIUS + restitution ** 2 * (DROP - RADIUS)
        print(f"C_R = {restitution}: first rebound tops out at {apex:.4f} m "
              f"(0.5 + C_R² · 9.5 = {expected:.4f} m)")
        # Sampled every 1/240 s, the top is missed by at most ½ g (1/480 s)² ≈ 2e-5 m.
        assert abs(apex - expected) < 1e-4, (apex, expected)
        axes.plot(t, y, label=f"C_R = {restitution}")
    axes.axhline(RADIUS, color="grey", linewidth=0.8)
    close_figure(args, figure, axes, "t [s]", "height of the centre y [m]",
                 "A ball dropped from 10 m bounces back to 0.5 + C_R² · 9.5 m")


if __name__ == "__main__":
    main()
