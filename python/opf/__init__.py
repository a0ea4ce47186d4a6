"""Object Permanence Filter toolkit, from Python.

    import opf
    tracker = opf.Tracker("opf", seed=1, particles=5000)
    estimates = tracker.step(0.0, {"cup": [0.4, 0.0, 0.1, 0, 0, 0, 1], "tray": None})
    estimates["cup"].position, estimates["cup"].covariance, estimates["cup"].mode

    columns = opf.track_log("log.csv", estimator="opf")   # a pandas DataFrame if pandas is there

The log format, the settings file and the estimate columns are those of the `opf` program
(docs/logs.md, experiments/configs/estimators.yaml, docs/library.md).
"""

from ._opf import Estimate, InputError, Tracker, estimators
from ._opf import _track_log

__all__ = ["Estimate", "InputError", "Tracker", "estimators", "track_log"]


def track_log(path, estimator="opf", seed=1, particles=5000, config=None, dataframe=True):
    """Replays the measurement log at `path` through `estimator` (the same frames and rows as
    `opf track`: one per object per frame, then the further hypotheses) and returns its columns:
    a pandas DataFrame when pandas is installed and `dataframe` is true, else a dict of numpy
    arrays (object, mode and model as lists of str)."""
    columns = _track_log(str(path), estimator=estimator, seed=seed, particles=particles,
                         config=config)
    if dataframe:
        try:
            import pandas
        except ImportError:
            return columns
        return pandas.DataFrame(columns)
    return columns
