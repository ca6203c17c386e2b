"""Minimal stand-ins for gymnasium.spaces.Box and Dict, used when gymnasium is not installed
(Debian does not ship it). Same attributes and methods as far as ParkingEnv's users need them."""

import numpy as np


class Box:
    """A box in R^n: shape, low, high, dtype; sample() draws uniformly (normally where unbounded)
    from the space's own generator, seeded by seed()."""

    def __init__(self, low, high, shape=None, dtype=np.float32, seed=None):
        self.dtype = np.dtype(dtype)
        if shape is None:
            shape = np.shape(low) if np.ndim(low) else np.shape(high)
        self.shape = tuple(shape)
        self.low = np.full(self.shape, low, dtype=self.dtype)
        self.high = np.full(self.shape, high, dtype=self.dtype)
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)
        return [seed]

    def sample(self):
        low = self.low.astype(np.float64)
        high = self.high.astype(np.float64)
        bounded = np.isfinite(low) & np.isfinite(high)
        out = self._rng.normal(size=self.shape)
        out = np.where(np.isfinite(low) & ~bounded, low + np.abs(out), out)
        out = np.where(np.isfinite(high) & ~bounded, high - np.abs(out), out)
        uniform = self._rng.uniform(np.where(bounded, low, 0.0), np.where(bounded, high, 1.0))
        out = np.where(bounded, uniform, out)
        return out.astype(self.dtype)

    def contains(self, x):
        x = np.asarray(x)
        return (x.shape == self.shape and np.can_cast(x.dtype, self.dtype, "same_kind")
                and bool(np.all(x >= self.low)) and bool(np.all(x <= self.high)))

    def __contains__(self, x):
        return self.contains(x)

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"


class Dict:
    """Named spaces (gymnasium.spaces.Dict): spaces, [key], sample(), contains()."""

    def __init__(self, spaces, seed=None):
        self.spaces = dict(spaces)
        self.seed(seed)

    def seed(self, seed=None):
        for i, space in enumerate(self.spaces.values()):
            space.seed(None if seed is None else seed + i)
        return [seed]

    def sample(self):
        return {key: space.sample() for key, space in self.spaces.items()}

    def contains(self, x):
        return (isinstance(x, dict) and set(x) == set(self.spaces)
                and all(space.contains(x[key]) for key, space in self.spaces.items()))

    def __contains__(self, x):
        return self.contains(x)

    def __getitem__(self, key):
        return self.spaces[key]

    def __repr__(self):
        return f"Dict({self.spaces!r})"
