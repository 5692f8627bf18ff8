"""Local transverse Mercator projection centred on the first ego fix.

A transverse Mercator centred on the scene keeps scale error below 1e-6 over a few kilometres, so the
scenario can use plain metres. The same PROJ string goes into the OpenDRIVE ``geoReference`` and to
netconvert, which puts the ``.xodr`` and the ``.xosc`` in one metric frame.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from pyproj import CRS, Transformer

from vei_scenario.clip.model import local_tmerc


@dataclass(frozen=True)
class LocalProjection:
    lat0_deg: float
    lon0_deg: float

    @property
    def proj_string(self) -> str:
        return local_tmerc(self.lat0_deg, self.lon0_deg)

    @cached_property
    def _forward(self) -> Transformer:
        return Transformer.from_crs(CRS.from_epsg(4326), CRS.from_proj4(self.proj_string), always_xy=True)

    @cached_property
    def _inverse(self) -> Transformer:
        return Transformer.from_crs(CRS.from_proj4(self.proj_string), CRS.from_epsg(4326), always_xy=True)

    def forward(self, lat_deg, lon_deg) -> tuple[np.ndarray, np.ndarray]:
        """WGS84 latitude/longitude (degrees) → local east/north (m)."""
        x, y = self._forward.transform(np.asarray(lon_deg, float), np.asarray(lat_deg, float))
        return np.asarray(x, float), np.asarray(y, float)

    def inverse(self, x_m, y_m) -> tuple[np.ndarray, np.ndarray]:
        """Local east/north (m) → latitude/longitude (degrees)."""
        lon, lat = self._inverse.transform(np.asarray(x_m, float), np.asarray(y_m, float))
        return np.asarray(lat, float), np.asarray(lon, float)

    def grid_north_offset_rad(self, lat_deg, lon_deg) -> np.ndarray:
        """Angle from grid north to true north, clockwise (the meridian convergence).

        Measured by projecting a 1e-5° step north instead of trusting a sign convention; it is zero on
        the central meridian and ~1e-5 rad a kilometre away at mid latitudes.
        """
        lat = np.asarray(lat_deg, float)
        lon = np.asarray(lon_deg, float)
        x0, y0 = self.forward(lat, lon)
        x1, y1 = self.forward(lat + 1e-5, lon)
        return np.arctan2(x1 - x0, y1 - y0)

    def heading_to_yaw(self, lat_deg, lon_deg, heading_deg) -> np.ndarray:
        """Course over ground (degrees clockwise from true north) → yaw (rad, counter-clockwise from +x)."""
        grid_heading = np.radians(np.asarray(heading_deg, float)) + self.grid_north_offset_rad(lat_deg, lon_deg)
        return np.pi / 2 - grid_heading

    def yaw_to_heading(self, lat_deg, lon_deg, yaw_rad) -> np.ndarray:
        """Inverse of :meth:`heading_to_yaw`, in degrees within [0, 360)."""
        grid_heading = np.pi / 2 - np.asarray(yaw_rad, float)
        return np.degrees(grid_heading - self.grid_north_offset_rad(lat_deg, lon_deg)) % 360.0
