"""What the example scripts share: one matplotlib figure, shown, or with --out FILE written to a
file without a display (the tests do that)."""
import argparse

import matplotlib


def open_figure(doc):
    """The parsed command line (its description the first line of `doc`), and a new figure and
    axes."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--out", help="write the figure to this file instead of showing it")
    args = parser.parse_args()
    if args.out:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(figsize=(8, 4.5))
    return args, figure, axes


def close_figure(args, figure, axes, xlabel, ylabel, title):
    """Labels the axes, adds the legend, then writes or shows the figure."""
    axes.set_xlabel(xlabel)
    axes.set_ylabel(ylabel)
    axes.set_title(title)
    axes.legend()
    if args.out:
        figure.savefig(args.out, dpi=100)
    else:
        import matplotlib.pyplot as plt
        plt.show()
