"""Object Permanence Filter toolkit, from Python.

    import opf
    tracker = opf.Tracker("opf", seed=1, particles=5000)
    estimates = tracker.step(0.0, {"cup": [0.4, 0.0, 0.1, 0, 0, 0, 1], "tray": None})
    estimates["cup"].position, estimates["cup"].covariance, estimates["cup"].mode

    columns = opf.track_log("log.csv", estimator="opf")   # a pandas DataFrame if pandas is there

The log format, the settings file and the estimate columns are those of the `opf` program
(docs/logs.md, experiments/configs/estimators.yaml, docs/library.md).
"""

import os

from ._opf import Estimate, InputError, Tracker, estimators, __version__
from ._opf import _track_log

__all__ = ["Estimate", "InputError", "Tracker", "estimators", "track_log", "__version__"]


def track_log(path, estimator="opf", seed=1, particles=None, config=None, dataframe=True, *,
              preset="default", camera=None, format=None, object=None, time_unit=None,
              length_unit=None, columns=None,
              frame_tolerance=None, rate=None, fill=True, covariance=False):
    """Replays the measurement log at `path` through `estimator` and returns the columns of the
    estimate file `opf track` writes for the same log, options and seed (one row per object per
    frame, then the further hypotheses): a pandas DataFrame when pandas is installed and
    `dataframe` is true, else a dict of numpy arrays (object, mode and model as lists of str).

    The options are `opf track`'s of the same names, with the same defaults and checks:
    particles (None: the config's, else 5000), config (a settings file's path or a dict),
    preset ("default" or "paper"), camera ([X, Y, Z] or "X,Y,Z", m; [X, Y, Z, 0]: infinitely
    far that way), format ("csv", "tum", "mot", "euroc" or "kitti"; None: detected, a TUM trajectory or
    an ASL CSV being named after its file unless object names it),
    object (the one object of a log without an object column), time_unit (s, ms, us, ns),
    length_unit (m, mm), columns ({"qx": "rx", ...} or "qx=rx,..."), frame_tolerance (s),
    rate (Hz), fill (False: --no-fill) and covariance (True: the 21 cov_* columns too)."""
    result = _track_log(os.fspath(path), estimator=estimator, seed=seed, particles=particles,
                        config=config, preset=preset, camera=camera, format=format,
                        object=object, time_unit=time_unit,
                        length_unit=length_unit, columns=columns,
                        frame_tolerance=frame_tolerance, rate=rate, fill=fill,
                        covariance=covariance)
    if dataframe:
        try:
            import pandas
        except ImportError:
            return result
        return pandas.DataFrame(result)
    return result
