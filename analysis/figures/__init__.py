"""Figure families: model (the initial cell), shapes (slices of snapshots), curves (time series).
Each module has draw(config, fig, ...) -> matplotlib Figure; render.draw picks the family and reads
its runs from a results folder; common.save writes PNG and PDF."""
