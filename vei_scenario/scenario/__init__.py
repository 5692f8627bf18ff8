"""The VEI scenario model: what a compiled scenario contains, independent of file formats."""
