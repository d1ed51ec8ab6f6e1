//! Reading a figure back, for the tests of every figure flexarm writes (`tests/figure.rs`: the
//! page's and `flexarm figure`; `tests/svg.rs`: `simulate --svg` and `map --svg`): its elements
//! in balance, its texts by class, each panel's axes as the figure states them, the triangles it
//! draws in a colour.

#![allow(dead_code)]

pub fn count(s: &str, pat: &str) -> usize {
    s.matches(pat).count()
}

/// A standalone SVG whose elements open and close in balance, with nothing non-finite in it.
pub fn assert_wellformed(svg: &str, what: &str) {
    assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""), "{what}");
    assert!(svg.trim_end().ends_with("</svg>"), "{what}");
    assert_eq!(count(svg, "<svg"), 1, "{what}");
    // Every element is closed in order: a stack of open tags.
    let mut stack: Vec<&str> = Vec::new();
    for piece in svg.split('<').skip(1) {
        let tag = piece.split('>').next().unwrap();
        assert!(piece.contains('>'), "{what}: unclosed tag {tag}");
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop(), Some(name.trim()), "{what}: </{name}> closes another element");
        } else if !tag.ends_with('/') {
            stack.push(tag.split([' ', '\n']).next().unwrap());
        }
    }
    assert!(stack.is_empty(), "{what}: left open {stack:?}");
    assert_eq!(count(svg, "<"), count(svg, ">"), "{what}: angle brackets balance (text is escaped)");
    for bad in ["NaN", "inf", "Infinity"] {
        assert!(!svg.contains(bad), "{what}: {bad} in the output");
    }
}

pub fn unescape(s: &str) -> String {
    s.replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", "\"").replace("&#39;", "'").replace("&amp;", "&")
}

/// The contents of the texts of a class, in order.
pub fn texts(svg: &str, class: &str) -> Vec<String> {
    svg.split(&format!("<text class=\"{class}\""))
        .skip(1)
        .map(|rest| unescape(rest.split_once('>').unwrap().1.split("</text>").next().unwrap()))
        .collect()
}

/// An attribute's value in a tag.
pub fn attr<'a>(tag: &'a str, name: &str) -> &'a str {
    tag.split(&format!(" {name}=\"")).nth(1).unwrap_or_else(|| panic!("no {name} in {tag}")).split('"').next().unwrap()
}

pub fn numbers(s: &str) -> Vec<f64> {
    s.split(' ').map(|v| v.parse().unwrap()).collect()
}

/// A panel's data area [x, y, w, h] and its axes' ranges, as the figure states them.
pub struct Axes {
    pub rect: Vec<f64>,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
}

impl Axes {
    pub fn of(svg: &str, id: &str) -> Axes {
        let tag = svg.split(&format!("data-panel=\"{id}\"")).nth(1).unwrap_or_else(|| panic!("no panel {id}"));
        let tag = tag.split('>').next().unwrap();
        Axes {
            rect: numbers(attr(tag, "data-rect")),
            x: numbers(attr(tag, "data-x-range")),
            y: numbers(attr(tag, "data-y-range")),
        }
    }

    /// The value at a point of the figure (linear axes).
    pub fn value(&self, p: [f64; 2]) -> [f64; 2] {
        let fx = (p[0] - self.rect[0]) / self.rect[2];
        let fy = (self.rect[1] + self.rect[3] - p[1]) / self.rect[3];
        [self.x[0] + fx * (self.x[1] - self.x[0]), self.y[0] + fy * (self.y[1] - self.y[0])]
    }

    /// The value at a point of the figure (logarithmic axes).
    pub fn log_value(&self, p: [f64; 2]) -> [f64; 2] {
        let fx = (p[0] - self.rect[0]) / self.rect[2];
        let fy = (self.rect[1] + self.rect[3] - p[1]) / self.rect[3];
        [self.x[0] * (self.x[1] / self.x[0]).powf(fx), self.y[0] * (self.y[1] / self.y[0]).powf(fy)]
    }
}

/// The triangles the figure draws in `color` in its layer `layer` ("static": the maps' cells and
/// contours, ρ(δ)'s curve; "frame": the rest), each as its three corners.
pub fn triangles_in(svg: &str, layer: &str, color: flexarm::plot::Color) -> Vec<[[f64; 2]; 3]> {
    let group = svg.split(&format!("<g id=\"{layer}\">")).nth(1).unwrap().split("</g>\n<g id=").next().unwrap();
    let fill = format!("fill=\"{}\"", color.with_alpha(1.0).css());
    let mut out = Vec::new();
    for path in group.split("<path d=\"").skip(1).filter(|p| p.split('>').next().unwrap().contains(&fill)) {
        let d = path.split('"').next().unwrap();
        for sub in d.split('M').filter(|s| s.contains('L')) {
            let v: Vec<f64> =
                sub.trim_end_matches('Z').replace('L', " ").split(' ').map(|x| x.parse().unwrap()).collect();
            out.push([[v[0], v[1]], [v[2], v[3]], [v[4], v[5]]]);
        }
    }
    out
}

/// The triangles the figure draws in `color` in the per-frame layer.
pub fn triangles(svg: &str, color: flexarm::plot::Color) -> Vec<[[f64; 2]; 3]> {
    triangles_in(svg, "frame", color)
}

pub fn centroid(t: &[[f64; 2]; 3]) -> [f64; 2] {
    [(t[0][0] + t[1][0] + t[2][0]) / 3.0, (t[0][1] + t[1][1] + t[2][1]) / 3.0]
}

pub fn luminance(hex: &str) -> f64 {
    let c = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).unwrap() as f64 / 255.0;
    0.2126 * c(1) + 0.7152 * c(3) + 0.0722 * c(5)
}

pub fn background(svg: &str) -> String {
    let tag = svg.split("<rect id=\"background\"").nth(1).unwrap().split('>').next().unwrap();
    attr(tag, "fill").to_string()
}
