"""A wrong value as a learner might reach it, for the tests of carried answers (chains, steps)."""


def moved(value, rng):
    """``value`` (a number, or rows of them) with the number, or one entry, moved by 5-60 % and a little more."""
    def move(v):
        return v + rng.choice((-1, 1)) * (abs(v) * rng.uniform(0.05, 0.6) + rng.uniform(0.05, 0.5))

    if isinstance(value, tuple):
        rows = [list(r) for r in value]
        i, j = rng.randrange(len(rows)), rng.randrange(len(rows[0]))
        rows[i][j] = move(rows[i][j])
        return tuple(map(tuple, rows))
    return move(value)
