//! Image files, plots and figure helpers. (Being written.)
