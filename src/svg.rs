//! Publication-ready SVG figures (stability maps, error traces) as plain strings.
