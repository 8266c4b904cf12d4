//! The ids of flam3's variations: their indices in flam3's list, which its numeric `var` lists
//! use and which the registry keeps.

/// The id of flam3's `linear` variation.
pub const LINEAR: u16 = 0;
/// The id of flam3's `sinusoidal` variation.
pub const SINUSOIDAL: u16 = 1;
/// The id of flam3's `spherical` variation.
pub const SPHERICAL: u16 = 2;
/// The id of flam3's `swirl` variation.
pub const SWIRL: u16 = 3;
/// The id of flam3's `horseshoe` variation.
pub const HORSESHOE: u16 = 4;
/// The id of flam3's `polar` variation.
pub const POLAR: u16 = 5;
/// The id of flam3's `handkerchief` variation.
pub const HANDKERCHIEF: u16 = 6;
/// The id of flam3's `heart` variation.
pub const HEART: u16 = 7;
/// The id of flam3's `disc` variation.
pub const DISC: u16 = 8;
/// The id of flam3's `spiral` variation.
pub const SPIRAL: u16 = 9;
/// The id of flam3's `hyperbolic` variation.
pub const HYPERBOLIC: u16 = 10;
/// The id of flam3's `diamond` variation.
pub const DIAMOND: u16 = 11;
/// The id of flam3's `ex` variation.
pub const EX: u16 = 12;
/// The id of flam3's `julia` variation.
pub const JULIA: u16 = 13;
/// The id of flam3's `bent` variation.
pub const BENT: u16 = 14;
/// The id of flam3's `waves` variation.
pub const WAVES: u16 = 15;
/// The id of flam3's `fisheye` variation.
pub const FISHEYE: u16 = 16;
/// The id of flam3's `popcorn` variation.
pub const POPCORN: u16 = 17;
/// The id of flam3's `exponential` variation.
pub const EXPONENTIAL: u16 = 18;
/// The id of flam3's `power` variation.
pub const POWER: u16 = 19;
/// The id of flam3's `cosine` variation.
pub const COSINE: u16 = 20;
/// The id of flam3's `rings` variation.
pub const RINGS: u16 = 21;
/// The id of flam3's `fan` variation.
pub const FAN: u16 = 22;
/// The id of flam3's `blob` variation.
pub const BLOB: u16 = 23;
/// The id of flam3's `pdj` variation.
pub const PDJ: u16 = 24;
/// The id of flam3's `fan2` variation.
pub const FAN2: u16 = 25;
/// The id of flam3's `rings2` variation.
pub const RINGS2: u16 = 26;
/// The id of flam3's `eyefish` variation.
pub const EYEFISH: u16 = 27;
/// The id of flam3's `bubble` variation.
pub const BUBBLE: u16 = 28;
/// The id of flam3's `cylinder` variation.
pub const CYLINDER: u16 = 29;
/// The id of flam3's `perspective` variation.
pub const PERSPECTIVE: u16 = 30;
/// The id of flam3's `noise` variation.
pub const NOISE: u16 = 31;
/// The id of flam3's `julian` variation.
pub const JULIAN: u16 = 32;
/// The id of flam3's `juliascope` variation.
pub const JULIASCOPE: u16 = 33;
/// The id of flam3's `blur` variation.
pub const BLUR: u16 = 34;
/// The id of flam3's `gaussian_blur` variation.
pub const GAUSSIAN_BLUR: u16 = 35;
/// The id of flam3's `radial_blur` variation.
pub const RADIAL_BLUR: u16 = 36;
/// The id of flam3's `pie` variation.
pub const PIE: u16 = 37;
/// The id of flam3's `ngon` variation.
pub const NGON: u16 = 38;
/// The id of flam3's `curl` variation.
pub const CURL: u16 = 39;
/// The id of flam3's `rectangles` variation.
pub const RECTANGLES: u16 = 40;
/// The id of flam3's `arch` variation.
pub const ARCH: u16 = 41;
/// The id of flam3's `tangent` variation.
pub const TANGENT: u16 = 42;
/// The id of flam3's `square` variation.
pub const SQUARE: u16 = 43;
/// The id of flam3's `rays` variation.
pub const RAYS: u16 = 44;
/// The id of flam3's `blade` variation.
pub const BLADE: u16 = 45;
/// The id of flam3's `secant2` variation.
pub const SECANT2: u16 = 46;
/// The id of flam3's `twintrian` variation.
pub const TWINTRIAN: u16 = 47;
/// The id of flam3's `cross` variation.
pub const CROSS: u16 = 48;
/// The id of flam3's `disc2` variation.
pub const DISC2: u16 = 49;
/// The id of flam3's `super_shape` variation.
pub const SUPER_SHAPE: u16 = 50;
/// The id of flam3's `flower` variation.
pub const FLOWER: u16 = 51;
/// The id of flam3's `conic` variation.
pub const CONIC: u16 = 52;
/// The id of flam3's `parabola` variation.
pub const PARABOLA: u16 = 53;
/// The id of flam3's `bent2` variation.
pub const BENT2: u16 = 54;
/// The id of flam3's `bipolar` variation.
pub const BIPOLAR: u16 = 55;
/// The id of flam3's `boarders` variation.
pub const BOARDERS: u16 = 56;
/// The id of flam3's `butterfly` variation.
pub const BUTTERFLY: u16 = 57;
/// The id of flam3's `cell` variation.
pub const CELL: u16 = 58;
/// The id of flam3's `cpow` variation.
pub const CPOW: u16 = 59;
/// The id of flam3's `curve` variation.
pub const CURVE: u16 = 60;
/// The id of flam3's `edisc` variation.
pub const EDISC: u16 = 61;
/// The id of flam3's `elliptic` variation.
pub const ELLIPTIC: u16 = 62;
/// The id of flam3's `escher` variation.
pub const ESCHER: u16 = 63;
/// The id of flam3's `foci` variation.
pub const FOCI: u16 = 64;
/// The id of flam3's `lazysusan` variation.
pub const LAZYSUSAN: u16 = 65;
/// The id of flam3's `loonie` variation.
pub const LOONIE: u16 = 66;
/// The id of flam3's `pre_blur` variation.
pub const PRE_BLUR: u16 = 67;
/// The id of flam3's `modulus` variation.
pub const MODULUS: u16 = 68;
/// The id of flam3's `oscilloscope` variation.
pub const OSCILLOSCOPE: u16 = 69;
/// The id of flam3's `polar2` variation.
pub const POLAR2: u16 = 70;
/// The id of flam3's `popcorn2` variation.
pub const POPCORN2: u16 = 71;
/// The id of flam3's `scry` variation.
pub const SCRY: u16 = 72;
/// The id of flam3's `separation` variation.
pub const SEPARATION: u16 = 73;
/// The id of flam3's `split` variation.
pub const SPLIT: u16 = 74;
/// The id of flam3's `splits` variation.
pub const SPLITS: u16 = 75;
/// The id of flam3's `stripes` variation.
pub const STRIPES: u16 = 76;
/// The id of flam3's `wedge` variation.
pub const WEDGE: u16 = 77;
/// The id of flam3's `wedge_julia` variation.
pub const WEDGE_JULIA: u16 = 78;
/// The id of flam3's `wedge_sph` variation.
pub const WEDGE_SPH: u16 = 79;
/// The id of flam3's `whorl` variation.
pub const WHORL: u16 = 80;
/// The id of flam3's `waves2` variation.
pub const WAVES2: u16 = 81;
/// The id of flam3's `exp` variation.
pub const EXP: u16 = 82;
/// The id of flam3's `log` variation.
pub const LOG: u16 = 83;
/// The id of flam3's `sin` variation.
pub const SIN: u16 = 84;
/// The id of flam3's `cos` variation.
pub const COS: u16 = 85;
/// The id of flam3's `tan` variation.
pub const TAN: u16 = 86;
/// The id of flam3's `sec` variation.
pub const SEC: u16 = 87;
/// The id of flam3's `csc` variation.
pub const CSC: u16 = 88;
/// The id of flam3's `cot` variation.
pub const COT: u16 = 89;
/// The id of flam3's `sinh` variation.
pub const SINH: u16 = 90;
/// The id of flam3's `cosh` variation.
pub const COSH: u16 = 91;
/// The id of flam3's `tanh` variation.
pub const TANH: u16 = 92;
/// The id of flam3's `sech` variation.
pub const SECH: u16 = 93;
/// The id of flam3's `csch` variation.
pub const CSCH: u16 = 94;
/// The id of flam3's `coth` variation.
pub const COTH: u16 = 95;
/// The id of flam3's `auger` variation.
pub const AUGER: u16 = 96;
/// The id of flam3's `flux` variation.
pub const FLUX: u16 = 97;
/// The id of flam3's `mobius` variation.
pub const MOBIUS: u16 = 98;

/// The seven variations of Fraktalai's menu, in menu order.
pub const THESIS_SEVEN: [u16; 7] = [LINEAR, SINUSOIDAL, SPHERICAL, SWIRL, HORSESHOE, POLAR, BENT];

/// Number of variations in flam3's list.
pub const FLAM3_COUNT: usize = 99;
