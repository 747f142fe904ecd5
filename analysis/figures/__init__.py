"""Figure families: model (the initial cell), shapes (slices of snapshots), curves (time series).
Each module has draw(config, fig, ...) -> matplotlib Figure; common.save writes PNG and PDF."""
