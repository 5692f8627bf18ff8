"""Road network: OpenStreetMap → OpenDRIVE through SUMO netconvert, or a road fitted to the ego track."""
