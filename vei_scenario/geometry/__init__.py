"""Geometry and reconstruction: map projection, time sync, ego frame → world, resampling, conflicts."""
