"""The picture of a study of error against cost (the ladder, the convergence study): per
panel, every setting as a point at (CPU time relative to a baseline, error relative to its
tolerance), green within tolerance, red not, the Pareto front (no other setting both cheaper
and more accurate) and the tolerance line at 1."""


def pareto_front(points):
    """[(cost, score)] of the points no other point beats in both cost and score, by cost."""
    front, best = [], float("inf")
    for cost, score in sorted(points):
        if score < best:
            front.append((cost, score))
            best = score
    return front


def plot(panels, path, xlabel, ylabel, tolerance_label="tolerance", cost_line=None):
    """panels: {title: [(name, cost, score, ok)]}, score = error / tolerance (1: at the
    tolerance); cost_line: (x, label) of a vertical line, e.g. a target cost. Writes a PNG."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = max(1, len(panels))
    fig, axes = plt.subplots(1, n, figsize=(6.0 * n, 5), squeeze=False)
    for ax, (title, points) in zip(axes[0], panels.items()):
        for name, cost, score, ok in points:
            ax.scatter(cost, score, c="tab:green" if ok else "tab:red", s=25)
            ax.annotate(name, (cost, score), fontsize=6, xytext=(3, 2), textcoords="offset points")
        front = pareto_front([(cost, score) for _, cost, score, _ in points])
        if front:
            ax.plot(*zip(*front), "k--", lw=0.8, label="Pareto front")
        ax.axhline(1.0, color="grey", lw=0.8, label=tolerance_label)
        if cost_line:
            ax.axvline(cost_line[0], color="grey", lw=0.8, ls=":", label=cost_line[1])
        ax.set_xscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.set_title(title)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
