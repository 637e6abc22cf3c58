"""Where each marked figure of README.md and docs/*.md comes from (check_figures.py reads them).

An entry either computes its figure from runs of the command line (`Computed`, checked by ctest
docs.figures every time) or reads it from a row of `gamephysics verify`'s report.md (`VerifyRow`,
checked by ./run.sh after the full verify). Each computation here is independent of the engine's
own measurement code: it reads the CSV that `simulate` and `oracle` write and compares with the
closed form computed from the scene file.
"""
import atexit
import csv
import json
import math
import pathlib
import re
import shutil
import subprocess
import tempfile


class Runner:
    """Runs `gamephysics simulate` and `oracle` once per scene and options; reads their CSV."""

    def __init__(self, root, binary):
        self.root, self.binary = pathlib.Path(root), pathlib.Path(binary)
        self.folder = pathlib.Path(tempfile.mkdtemp(prefix="gp_figures_"))
        atexit.register(shutil.rmtree, self.folder, ignore_errors=True)
        self.cache = {}

    def scene(self, name, **patch):
        """The scene file scenes/NAME.json with PATCH's fields replaced; its path."""
        if not patch:
            return self.root / "scenes" / f"{name}.json"
        data = json.loads((self.root / "scenes" / f"{name}.json").read_text())
        data.update(patch)
        path = self.folder / f"{name}_{len(self.cache)}.json"
        path.write_text(json.dumps(data))
        return path

    def run(self, command, name, patch=None, options=()):
        """The trajectory {body: [(t, x, y, angle, vx, vy, omega), ...]} of COMMAND on the scene."""
        key = (command, name, json.dumps(patch or {}, sort_keys=True), tuple(options))
        if key not in self.cache:
            out = self.folder / f"run_{len(self.cache)}.csv"
            scene = self.scene(name, **(patch or {}))
            subprocess.run([str(self.binary), command, str(scene), "--out", str(out), *options],
                           check=True, stdout=subprocess.DEVNULL)
            trajectory = {}
            with open(out, newline="") as f:
                for row in csv.DictReader(f):
                    values = tuple(float(row[k]) for k in ("t", "x", "y", "angle", "vx", "vy",
                                                            "omega"))
                    trajectory.setdefault(row["body"], []).append(values)
            self.cache[key] = trajectory
        return self.cache[key]

    def simulate(self, name, patch=None, integrator=None):
        return self.run("simulate", name, patch,
                        ("--integrator", integrator) if integrator else ())

    def oracle(self, name):
        return self.run("oracle", name)

    def output(self, *args):
        """What `gamephysics ARGS` prints (once per ARGS)."""
        if args not in self.cache:
            self.cache[args] = subprocess.run([str(self.binary), *args], check=True, text=True,
                                              capture_output=True).stdout
        return self.cache[args]

    def scene_data(self, name):
        return json.loads((self.root / "scenes" / f"{name}.json").read_text())


class Report:
    """The rows of a report.md of `gamephysics verify`: {(section, check): [measured, ...]} (rows
    of one name differ in their SRS ids)."""

    def __init__(self, folder):
        self.rows, section = {}, None
        for line in (pathlib.Path(folder) / "report.md").read_text().splitlines():
            if line.startswith("## "):
                section = line[3:]
            elif line.startswith("|") and section:
                cells = re.split(r"(?<!\\)\|", line)[1:-1]
                if len(cells) == 5:
                    key = (section, cells[0].replace("\\|", "|"))
                    self.rows.setdefault(key, []).append(cells[2].replace("\\|", "|"))


class Computed:
    """A figure computed by FUNCTION(runner) from runs of the command line SOURCE names."""

    def __init__(self, source, function):
        self.source, self.function = source, function

    def measure(self, runner, report):
        return self.function(runner)


class VerifyRow:
    """A figure read from the measured text of a row of verify's report: PATTERN's first group."""

    def __init__(self, section, check, pattern, long=False):
        self.section, self.check, self.pattern, self.long = section, check, pattern, long
        self.source = f"verify{' --long' if long else ''}: {section} / {check}"

    def measure(self, runner, report):
        if report is None:
            return None
        measured = report.rows.get((self.section, self.check))
        if measured is None:
            if self.long:
                return None
            raise LookupError(f"no row '{self.check}' in section '{self.section}' of the report")
        for text in measured:
            match = re.search(self.pattern, text)
            if match:
                return float(match.group(1))
        raise LookupError(f"'{self.pattern}' not in the row '{self.check}': {measured}")

    def skip_reason(self, report):
        if report is None:
            return "from verify's report: ./run.sh checks it (check_figures.py --report)"
        return "from verify --long: ./run.sh --long checks it"


# --- the computations ----------------------------------------------------------------------------


def at(rows, t):
    """The row of a body's trajectory at the output instant nearest t."""
    return min(rows, key=lambda r: abs(r[0] - t))


def largest_distance(a, b):
    """The largest distance between two trajectories' centres of mass at their common instants."""
    worst = 0.0
    for body, rows in a.items():
        other = {round(r[0], 9): r for r in b[body]}
        for r in rows:
            s = other[round(r[0], 9)]
            worst = max(worst, math.hypot(r[1] - s[1], r[2] - s[2]))
    return worst


def circular_orbit(scene):
    """The exact two-body circular orbit from a scene's initial state: body → position at t."""
    (a, b), big_g = scene["bodies"], scene["G"]
    mass = a["mass"] + b["mass"]
    centre = [(a["mass"] * pa + b["mass"] * pb) / mass
              for pa, pb in zip(a["position"], b["position"])]
    d = math.dist(a["position"], b["position"])
    omega = math.sqrt(big_g * mass / d**3)
    # Counter-clockwise when the angular momentum about the centre is positive.
    spin = sum(body["mass"] * ((body["position"][0] - centre[0]) * body["velocity"][1] -
                               (body["position"][1] - centre[1]) * body["velocity"][0])
               for body in (a, b))
    omega = math.copysign(omega, spin)

    def position(body, t):
        rx, ry = body["position"][0] - centre[0], body["position"][1] - centre[1]
        c, s = math.cos(omega * t), math.sin(omega * t)
        return centre[0] + c * rx - s * ry, centre[1] + s * rx + c * ry

    return {body["name"]: (lambda t, body=body: position(body, t)) for body in (a, b)}


def orbit_error_exact(runner, run):
    """The largest distance of a run of scenes/orbit.json from the exact circle."""
    exact = circular_orbit(runner.scene_data("orbit"))
    return max(math.dist(r[1:3], exact[body](r[0])) for body, rows in run.items() for r in rows)


def kinetic_energy(run, t, mass, moment):
    """Σ ½ m v² + ½ I ω² over the bodies of a run of equal bodies, at the instant nearest t."""
    total = 0.0
    for rows in run.values():
        r = at(rows, t)
        total += 0.5 * mass * (r[4] ** 2 + r[5] ** 2) + 0.5 * moment * r[6] ** 2
    return total


def rise_after_first_bounce(runner):
    rows = runner.simulate("bouncing_ball")["ball"]
    first = next(i for i in range(1, len(rows)) if rows[i][5] > 0 > rows[i - 1][5])
    last = next(i for i in range(first + 1, len(rows)) if rows[i][5] < 0 < rows[i - 1][5]) + 1
    return max(r[2] for r in rows[first:last])


SEQUENTIAL = {"direct_solve_points": 0}
# The passes alone above 64 points: no exact solve of a resting island's first step.
UNSEEDED = {"direct_solve_resting_points": 0, "duration": 3.0}


def top_box(runner, patch, t):
    """The top box of heavy_stack at the instant nearest t, and at 0."""
    rows = runner.simulate("heavy_stack", patch)["box9"]
    return at(rows, t), rows[0]


def largest_final_displacement(run):
    """The largest distance of a body's centre of mass at the end of a run from its start."""
    return max(math.dist(rows[-1][1:3], rows[0][1:3]) for rows in run.values())


def audit_figure(pattern):
    """A number of the SRS audit that `gamephysics audit` prints: PATTERN's first group."""
    def measure(runner):
        printed = runner.output("audit", "--root", str(runner.root), "--out",
                                str(runner.folder / "audit"))
        return float(re.search(pattern, printed).group(1))
    return Computed("gamephysics audit", measure)


def verify_rows():
    """The figures of the README's headline list and hard cases read from verify's report."""
    accuracy, hard = "accuracy against the oracle", "hard cases"
    order = "order of convergence"
    stack = "10-box stack, mass ratio 1:100, heavy on top, 10 s"
    rows = {
        "readme.ball.position": (accuracy, "bouncing_ball, velocity_verlet, dt = 0.0167 s",
                                 r"^position (\S+) m"),
        "readme.ball.collision_time": (accuracy, "bouncing_ball, velocity_verlet, dt = 0.0167 s",
                                       r"t_c (\S+) s"),
        "readme.ball.oracle_error": (
            accuracy, "bouncing_ball: oracle's own error, rtol = atol = 1e-12 against 1e-14",
            r"^position (\S+) m"),
        "readme.projectile.verlet": (accuracy, "projectile, velocity_verlet, dt = 0.01 s",
                                     r"^position (\S+) m"),
        "readme.projectile.rk4": (accuracy, "projectile, rk4, dt = 0.01 s", r"^position (\S+) m"),
        "readme.projectile.euler": (accuracy, "projectile, symplectic_euler, dt = 0.01 s",
                                    r"^position (\S+) m"),
        "readme.spin.verlet": (accuracy, "spinning_box, velocity_verlet, dt = 0.01 s",
                               r"orientation (\S+) rad"),
        "readme.spin.euler": (accuracy, "spinning_box, symplectic_euler, dt = 0.01 s",
                              r"orientation (\S+) rad"),
        "readme.conservation.momentum": ("conservation over long runs",
                                         "orbit, velocity_verlet, 100000 steps",
                                         r"linear momentum drift (\S+)"),
        "readme.stack.direct": (hard, stack, r"largest displacement (\S+) m"),
        "readme.stack.sequential": (hard, stack, r"topples: (\S+) m"),
    }
    for integrator in ("symplectic_euler", "velocity_verlet", "rk4"):
        rows[f"verify.order.{integrator}"] = (
            order, f"orbit, {integrator}, dt = 0.04 s halved 3 times", r"observed order (\S+)")
    return {key: VerifyRow(*row) for key, row in rows.items()}


def long_rows():
    """The 1e6-step figures, from the report of `verify --long`."""
    rows = {}
    for scene, bodies in (("pyramid20", 211), ("rain1000", 1001)):
        label = f"{scene} ({bodies} bodies), 1000000 steps: "
        rows[f"readme.long.{scene}.largest_coordinate"] = VerifyRow(
            "long runs", label + "no body leaves the box it starts in",
            r"largest \|x\| or \|y\| (\S+) m", long=True)
        rows[f"readme.long.{scene}.memory_growth"] = VerifyRow(
            "long runs", label + "resident memory does not grow",
            r"growth (\S+) MiB after the first tenth", long=True)
    return rows


def registry():
    simulate = "gamephysics simulate scenes/{}.json"
    return {
        **verify_rows(),
        **long_rows(),
        # README.md, the SRS audit
        "readme.audit.items": audit_figure(r"catalogue +(\d+) items"),
        "readme.audit.functions": audit_figure(r"functions +(\d+) registered"),
        "readme.audit.consistent": audit_figure(r"dimensional checks +(\d+) passed"),
        "readme.audit.inconsistent": audit_figure(r"(\d+) failed as written"),
        "readme.audit.errata": audit_figure(r"errata +(\d+) "),
        "readme.audit.edges_matched": audit_figure(r"edges +(\d+) matched"),
        "readme.audit.edges_srs_only": audit_figure(r"(\d+) missing from the code"),
        "readme.audit.edges_code_only": audit_figure(r"(\d+) extra in the code"),
        "readme.audit.edges_explained": audit_figure(r"(\d+)/\d+ differences explained"),
        # docs/tutorial.md, lesson 1
        "tutorial.projectile.vy_1s": Computed(
            simulate.format("projectile"),
            lambda r: at(r.simulate("projectile")["projectile"], 1.0)[5]),
        "tutorial.projectile.ke_1s": Computed(
            simulate.format("projectile"),
            lambda r: kinetic_energy(r.simulate("projectile"), 1.0,
                                     r.scene_data("projectile")["bodies"][0]["mass"], 0.0)),
        "tutorial.projectile.y_end": Computed(
            simulate.format("projectile"),
            lambda r: r.simulate("projectile")["projectile"][-1][2]),
        "tutorial.projectile.verlet_error": Computed(
            "simulate and oracle of scenes/projectile.json",
            lambda r: largest_distance(r.simulate("projectile"), r.oracle("projectile"))),
        "tutorial.projectile.euler_error": Computed(
            "simulate --integrator symplectic_euler and oracle of scenes/projectile.json",
            lambda r: largest_distance(r.simulate("projectile", integrator="symplectic_euler"),
                                       r.oracle("projectile"))),
        # lesson 2
        "tutorial.bounce.rise": Computed(simulate.format("bouncing_ball"), rise_after_first_bounce),
        # lesson 3: ½ I ω² with I = m (w² + h²) / 12 = 1/6 kg·m²
        "tutorial.spin.energy_3s": Computed(
            simulate.format("spinning_box"),
            lambda r: kinetic_energy(r.simulate("spinning_box"), 3.0, 1.0, 1.0 / 6.0)),
        # lesson 5: against the exact circle, and against the oracle
        **{f"tutorial.orbit.{name}_error": Computed(
            f"simulate --integrator {integrator} of scenes/orbit.json against the exact circle",
            lambda r, i=integrator: orbit_error_exact(r, r.simulate("orbit", integrator=i)))
           for name, integrator in (("euler", "symplectic_euler"), ("verlet", "velocity_verlet"),
                                    ("rk4", "rk4"))},
        "tutorial.orbit.rk4_oracle_distance": Computed(
            "simulate --integrator rk4 and oracle of scenes/orbit.json",
            lambda r: largest_distance(r.simulate("orbit", integrator="rk4"), r.oracle("orbit"))),
        "tutorial.orbit.oracle_error": Computed(
            "oracle of scenes/orbit.json against the exact circle",
            lambda r: orbit_error_exact(r, r.oracle("orbit"))),
        # lesson 6: pyramid20's boxes are 1 kg, I = 1/6 kg·m²
        "tutorial.pyramid.ke_exact_3s": Computed(
            simulate.format("pyramid20"),
            lambda r: kinetic_energy(r.simulate("pyramid20", {"duration": 3.0}), 3.0, 1.0, 1 / 6)),
        "tutorial.pyramid.ke_0.5s": Computed(
            simulate.format("pyramid20") + " with direct_solve_resting_points 0",
            lambda r: kinetic_energy(r.simulate("pyramid20", UNSEEDED), 0.5, 1.0, 1 / 6)),
        "tutorial.pyramid.ke_3s": Computed(
            simulate.format("pyramid20") + " with direct_solve_resting_points 0",
            lambda r: kinetic_energy(r.simulate("pyramid20", UNSEEDED), 3.0, 1.0, 1 / 6)),
        "tutorial.heavy.sideways_10s": Computed(
            simulate.format("heavy_stack"),
            lambda r: max(abs(row[1]) for row in r.simulate("heavy_stack")["box9"])),
        "tutorial.sequential.sink_cm_0.1s": Computed(
            simulate.format("heavy_stack") + " with direct_solve_points 0",
            lambda r: -100 * (top_box(r, SEQUENTIAL, 0.1)[0][2] - top_box(r, SEQUENTIAL, 0)[1][2])),
        "tutorial.sequential.angle_10s": Computed(
            simulate.format("heavy_stack") + " with direct_solve_points 0",
            lambda r: abs(math.remainder(top_box(r, SEQUENTIAL, 10.0)[0][3], 2 * math.pi))),
        "tutorial.sequential.speed_10s": Computed(
            simulate.format("heavy_stack") + " with direct_solve_points 0",
            lambda r: math.hypot(*top_box(r, SEQUENTIAL, 10.0)[0][4:6])),
        # README.md, hard cases: the same column with sequential impulses alone, up to 160 passes
        "readme.stack.160_passes_mm": Computed(
            simulate.format("heavy_stack") + " with direct_solve_points 0, velocity_iterations 160",
            lambda r: 1e3 * largest_final_displacement(
                r.simulate("heavy_stack", {**SEQUENTIAL, "velocity_iterations": 160}))),
    }
