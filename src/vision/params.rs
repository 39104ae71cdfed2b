//! Every threshold of the tracker in one place, with its default and why (as
//! rapier's `IntegrationParameters` does for a physics step): `track`'s options fill
//! the few a user sets (`--roi`, `--ball-at`), the rest are the tracker's own.

/// A rectangle of the frame, px: left, top, width, height.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Roi {
    pub x: f64,
    pub y: f64,
    pub width: f64,
    pub height: f64,
}

impl Roi {
    /// True when the point `(x, y)` (px) lies inside.
    pub fn contains(&self, x: f64, y: f64) -> bool {
        x >= self.x && x < self.x + self.width && y >= self.y && y < self.y + self.height
    }
}

/// The tracker's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Params {
    /// Where to look (`--roi`); `None`, the whole frame. Default `None`.
    pub roi: Option<Roi>,
    /// A point on one ball in the first frame, px (`--ball-at`, a click in the app):
    /// the blob under it is a ball whatever else the frame holds. Default `None`.
    pub ball_at: Option<(f64, f64)>,
    /// The balls' radius in the frame, px, taken as known from the first frame (as a
    /// seed's outline sets it), then learned from the fits as without it: set when
    /// the clip is tracked again at the radius its clear outlines agree on
    /// ([`super::Tracker::radius_contradicted`]). Default `None`.
    pub radius_px: Option<f64>,
    /// Smallest ball radius looked for, px. Default 8: below that the outline has
    /// too few edge pixels for a sub-pixel circle (≈ 50 points on a half circle).
    pub min_radius: f64,
    /// Width the frame is reduced to for the coarse look (the background and the
    /// blobs), px. Default 320: a 1080p frame by 6, which keeps a ball of 8 px
    /// radius over 2 coarse pixels and costs ~1/36 of the frame's pixels.
    pub coarse_width: usize,
    /// Frames kept (reduced) to learn the background from: their per-pixel median.
    /// Default 48: enough that a ball resting for a third of the clip is outvoted,
    /// few enough that the median costs little (48 × 320 × 180 bytes a plane).
    pub background_frames: usize,
    /// A coarse pixel differs from the background when its difference exceeds this
    /// many times the frame's scatter of differences. Default 5: noise passes one
    /// pixel in ~10⁵ (a 320 × 180 frame: under one).
    pub differ_sigmas: f64,
    /// … and at least this many levels. Default 10: the step an h264 encode at high
    /// compression leaves at sharp edges of the bench (ringing, blocks).
    pub differ_levels: f64,
    /// A clip in which no ball is found at `differ_levels` is tracked once more with
    /// this floor (`input::video::tracked`): a black ball on a dark wall differs from
    /// it by 4–8 levels at its limb, so that only its lit part passes 10 and is
    /// taken for no ball at all. Default 6: at 4 the floor passes the limb's noise
    /// (the looks' black balls' radii scatter by 6 %); lowered for every clip, 6
    /// gives wrong scales (docs/tracking.md). A floor at `differ_levels` or above
    /// never tracks again.
    pub faint_levels: f64,
    /// Weight of a colour difference (U, V) against one of brightness. Default 2: the
    /// colour planes span about half the levels brightness does for the same
    /// saturation change, and a coloured ball on a wall of its brightness differs
    /// only in them.
    pub colour_weight: f64,
    /// A shadow: darker than the background, by no more than this share of its
    /// brightness, and of the same hue (colour difference scaled as the brightness,
    /// within [`Params::shadow_hue_levels`]). Default 0.5: a cast shadow under a lamp
    /// keeps at least half the light; a black ball on a grey wall is darker still.
    pub shadow_darkest: f64,
    /// Colour difference levels a shadow's hue may differ from the lit background's.
    /// Default 6: compression and noise move U and V by a few levels.
    pub shadow_hue_levels: f64,
    /// An outline is poor below this share of its circle's 10° sectors covered by
    /// edge points. Default 0.35: the rail hides up to the lower half, a blurred or
    /// touching ball leaves less.
    pub min_coverage: f64,
    /// … once the balls' radius is known (from the first fits), below this share.
    /// Default 0.28: a steel or white ball on a wall of its brightness shows an edge
    /// only along its top (31–33 % of the circle on such looks); the fit's radius
    /// must then agree with the known one within `max_radius_spread` (not only
    /// `radius_tolerance`) and with the clip's other fits (`odd_radius`).
    pub min_coverage_known: f64,
    /// … and below this share even then, unless the arc is sharp: an outline covering
    /// at least `min_coverage_sharp` of its circle is kept, once the balls' radius is
    /// known, when its points scatter by at most `sharp_rms` px about it and its radius
    /// lies within `sharp_radius` of the known one. Default 0.19 (7 sectors, 70°): a
    /// black ball on a cluttered wall of its own brightness shows a clean edge only
    /// where the wall behind it is lighter (looks table, seed 9: fits of 0.2–0.3
    /// coverage at 0.05–0.15 px RMS, their centres 0.1–0.8 px from the truth, where the
    /// wider outlines mixed in the clutter's edges at 1.1–1.4 px RMS).
    pub min_coverage_sharp: f64,
    /// An outline with edge points within this many degrees of straight down and
    /// none within it of level, on either side, is not a ball
    /// (`circle::Outline::seen_over_a_rail`); 0 takes it. Default 20: a rail hides
    /// a ball from below, so what shows a ball's bottom shows its sides too.
    pub rail_view_deg: f64,
    /// See `min_coverage_sharp`. Default 0.25 px: a sharp edge gives 0.05–0.2 px.
    pub sharp_rms: f64,
    /// See `min_coverage_sharp`. Default 0.03: a short arc's radius is its least sure
    /// number; one off by more is the clutter's or a wrong circle.
    pub sharp_radius: f64,
    /// An outline is poor when its edge points scatter more than this about the
    /// circle, px RMS. Default 1.0: a sharp edge gives 0.1–0.3 px, a blur or a
    /// non-round blob more.
    pub max_rms: f64,
    /// Both balls have one radius: a fit farther than this share from the radius
    /// found so far is not a ball. Default 0.15 (a blur widens the edge by a few %).
    pub radius_tolerance: f64,
    /// A ball fitted smaller than this share of the blob it was found in is not the
    /// ball (the mark, a highlight); so, before the balls' radius is known, is a fit
    /// inside another blob of its frame smaller than this share of it (that blob's
    /// mark or highlight found as a blob of its own: the looks table's seed 15, a
    /// dark mark of 11.8 px fitted in colour inside its ball's blob of 63–87 px, set
    /// the radius). Default 0.6: the blob of a ball is the ball plus at most a
    /// shadow's fringe.
    pub smallest_in_blob: f64,
    /// A blob of the difference from the background is opened (eroded, then grown
    /// back) by a square this share of its height across (rounded down to whole
    /// coarse pixels either side of the middle one: blobs under 8 coarse pixels tall
    /// are left whole), and where the blob gave no outline about its middle, one is
    /// sought about the opened blob's ball (`detect::Blob::core`). Default 0.125: a
    /// ball differs from the background over a solid disc, the ragged fringe it drags
    /// in a compressed clip or where the background was learned partly with the balls
    /// in it (a mesh of one- and two-pixel lines: looks table, seeds 35 and 39, blobs
    /// 1.2–1.9 radii wide for 1.0–1.1 opened) falls away; 0 leaves blobs whole.
    /// Not where the background is learned at full resolution (frames under 640 px
    /// wide), where the blob rule (`outer_agree`) judges locks inside larger blobs.
    pub fringe_share: f64,
    /// Before the balls' radius is known, a coloured ball's blob (the median colour
    /// of its core's upper disc more than `grey_levels` from none) whose solid core
    /// (`detect::Blob::core`) is under this share of its radius is fitted at the
    /// core first, and whole only where the core gives no outline. Default 0.8: the
    /// full looks' seed 1 (purple balls on a yellow and grey checker, 240 frames/s,
    /// crf 31; blobs 1.6 radii wide, a checker's edges about the moving ball joined
    /// to it) had a first lock of the blob's size, 41 px for 25.5, and no ball found;
    /// a core nearer its blob's size is the ball with a thin fringe, and fitting it
    /// first changed three other full looks' centres (seed 45's RMS 0.39 → 0.71 px)
    /// and gained none. Grey balls are left out: a black ball's core can be its lit
    /// part alone (full look 9: 15 px for 24.4, μ_k 0.086 for 0.170). 0: never.
    pub core_first: f64,
    /// The first lock (before the balls' radius is known) is checked against the
    /// outermost circular edge of either sign about it (`circle::outermost`): a
    /// ball's outline is the outermost closed circular edge of the blob that moves.
    /// That edge is looked for out to this many of the lock's radii. Default 1.7:
    /// about 1 / `smallest_in_blob`, the largest ball a lock inside it can be.
    pub outer_reach: f64,
    /// … where the luma steps by at least this many levels across 2 px. Default 10
    /// (as `differ_levels`): 6 found a low-contrast limb on one more small look but
    /// took the wall's and the rail's edges on another (small looks' seed 1, a scale
    /// 15 ± off).
    pub outer_step: f64,
    /// … no farther than this many px (plus one coarse pixel) beyond the last place
    /// on each ray where the frame differs from its background. Default 2: a limb
    /// shaded to the wall's brightness may not differ, its edge a pixel or two out;
    /// the wall's own edges farther out (checkers, clutter) are not the ball's.
    pub outer_margin: f64,
    /// … and the lock and that edge's circle agree when their radii and their
    /// centres are within this share of the lock's radius. Default 0.1: the same
    /// outline found both ways is within a few %; a lock on the lit top of a ball
    /// (small looks, seed 38: 8.5 px for 12.3) or reaching into the rail (seed 1:
    /// 20.0 px for 14.3) is 25–40 % off. When they disagree, the outline of either
    /// sign about the outer circle is taken if it is a clear one that agrees with its
    /// own outermost edge, else the lock is poor. Where the background is learned at
    /// full resolution, a lock is poor too when the blob that differs from the
    /// background about it is a clear circle larger than it by more than this share
    /// and `outer_margin` (its limb steps too little for an edge: small looks' seed
    /// 11, a steel ball on wood grain, 12.2 px for 16.2).
    pub outer_agree: f64,
    /// The search window about the predicted centre, in radii. Default 0.5: a ball
    /// moves under a radius a frame at any rate used for this experiment (1 m/s at
    /// 30 frames/s is 33 mm, over a 12 mm ball's radius: there the window grows with
    /// the speed seen).
    pub window_radii: f64,
    /// Two balls touch (an impact, outlines merge) when their gap is under this, px.
    /// Default 2.
    pub touch_gap: f64,
    /// Refuse when the centres scatter across the groove's line by more than this
    /// share of the radius (RMS). Default 0.15: a ball rolls on the rail, its
    /// centre's height stays within the pixel noise; a "ball" that swings across
    /// the groove is something else.
    pub max_across: f64,
    /// A ball travels at least this many radii over the clip (the span of its
    /// centres); where none does, what was found stands still in every frame (a
    /// disc of the bench, kept as a target at rest) and no tracks are given.
    /// Default 0.25: a rolling ball crosses a quarter of its radius in a fraction
    /// of a second (7 mm at 4 cm/s in 0.17 s, 10 frames at 60 frames/s), while the
    /// disc of clutter taken for a ball (full look 80) stayed within 0.01 of its
    /// radius.
    pub least_travel: f64,
    /// The mark stands out from the ball's surface by at least this many pixel-noise
    /// scatters … Default 6.
    pub mark_sigmas: f64,
    /// … and this many levels. Default 10 (a glossy ball's shading texture is less).
    pub mark_levels: f64,
    /// The mark is located by the centroid of its contrast against the ball's
    /// shading above this share of its peak (less that share). Default 0.3: the
    /// shading's curvature, which a plane misses by a few levels, weighed over the
    /// whole spot's disc and pulled the centroid of a mark near the limb up to 5 px
    /// toward the centre; a drawn mark stands out by tens of levels.
    pub mark_cut: f64,
    /// The mark is then measured again by a model of a drawn disc over the ball's
    /// shading (`mark_fit`), and the model's place taken where its edge, a soft
    /// step, is no softer than this, px (0: the centroid always). Default 1.4: on
    /// 30 of the full looks table's looks (1,156 marks, the finder copied in a
    /// script), 1,105 edges came out 0.3–1.4 px; the model's place taken at any
    /// softness left a pooled sum of squared errors of 372 px² against the
    /// centroid's 442, taken up to 1.2, 1.4 and 1.6 px 322, 317 and 334: softer, the
    /// model has fitted something else than a disc, most of all the highlight's glow
    /// beside look 10's light marks on black balls (1.5–2.2 px), and put the mark
    /// farther off than the centroid.
    pub mark_soft: f64,
    /// A blob wider than this many balls (the radius known) is searched for balls
    /// of that radius on the frame's edges even where a ball was fitted in it (a
    /// ball and the smear of changed blocks it drags in a compressed clip).
    /// Default 1.3: a ball's blob is its width, plus a pixel or two of blur.
    pub wide_blob: f64,
    /// A ball of the wall's brightness is, to the look against a smooth surface of
    /// luma, two blobs: its lit part, brighter than the wall, and its shaded part,
    /// darker. Two or more such blobs inside one blob that differs from the
    /// background (within its box, give or take a coarse pixel), each narrower than
    /// this share of its width, are parts of that one ball: they are neither fitted
    /// nor counted as balls. Default 0.75 (the parts are 0.3–0.6 of it on the looks
    /// table's seed 43, a green ball on a magenta grainy wall of its brightness,
    /// refused before as "more than two balls" in 82 of 95 frames; one ball's blob
    /// inside a blob that also holds its shadow or smear is kept); 0 keeps them all.
    pub part_width: f64,
    /// A ball whose outline in brightness is poor (too little of it, or scattered)
    /// is sought in colour instead (the frame's colour difference from the
    /// background) when it is dark and grey: the median brightness of its disc's
    /// upper half under this many levels … Default 64: a black ball (30–50 on the
    /// looks table) on a wall of its brightness that differs from it in colour
    /// (seeds 9 and 10), its outline of both signs mixing in the wall's edges. Not
    /// a steel, white or coloured ball: on the looks table their colour outlines
    /// took in the shadow and the motion's smear (seeds 15, 16, 32: wrong μ_k).
    pub dark_ball: f64,
    /// … and its median colour within this many levels of none (U, V of 128).
    /// Default 6 (`shadow_hue_levels`).
    pub grey_levels: f64,
    /// A coloured ball (its median colour more than `grey_levels` from none) whose
    /// outline in colour scatters by at most this many px RMS about its circle, and
    /// whose radius lies farther from its outline in brightness than `outer_agree`,
    /// is that outline in colour. Default 0.7 (a clear outline in brightness
    /// scatters by up to `max_rms`, 1 px; in colour, on half-size planes, a clear
    /// edge by 0.2–0.6 px): the looks table's seed 26, balls of 12.35 px on a dark
    /// rail whose outlines in brightness took in the rail (14.9–16.9 px).
    pub colour_clear_rms: f64,
    /// Before the balls' radius is known, one frame's good fits whose radii lie
    /// farther apart than this share of the largest set no radius (none of them is
    /// kept). Default 0.15 (`radius_tolerance`): both balls have one radius; two first
    /// locks that disagree are a circle through a ball's top and the fringe joined to
    /// its blob and the ball (the median of two is the larger, the wrong one on the
    /// looks table's seeds 1, 23 and 26), or a ball's lit part and the ball.
    pub locks_agree: f64,
    /// The balls' radius is confirmed when each ball's fits found about its blobs'
    /// own guesses (not sought at the radius) have medians within this share of the
    /// radius of each other and of it; only then is a blob of about a ball's width
    /// whose own guess gave no outline sought at that radius. Default 0.05
    /// (`max_radius_spread`): a first lock a few % off, imposed on every blob, locks
    /// its error in (the looks table's seed 23: 1.26 R, μ_k 0.140 for 0.17).
    pub confirm_spread: f64,
    /// A circle of the balls' radius on the frame's edges needs edge votes from at
    /// least this share of its length (`hough::centres`). Default 0.2: the upper
    /// half shows above the rail, its edge two or three pixels thick, so a ball's
    /// arc gives about 0.5 or more; a wall's grain and a smear's blocks scatter
    /// theirs.
    pub hough_arc: f64,
    /// Which marks found are a ball's own ([`super::mark_check`]).
    pub marks: MarkChecks,
    /// A fit farther than this share of the radius across the groove from where its
    /// ball's other fits put the line is not the ball (a circle fitted to the smear a
    /// moving ball leaves in a compressed clip, to the wall's pattern): a ball rolls
    /// along its groove, its centre's height within the pixel noise. Default 0.25.
    pub off_the_line: f64,
    /// A fit whose radius is farther than this many robust scatters of every fit's
    /// radius from their median … Default 3: a circle fitted partly to something
    /// else (the wall's pattern, a compression smear) is off in its radius and its
    /// centre alike.
    pub odd_radius: f64,
    /// … and farther than this share of it is left out. Default 0.02 (half a pixel
    /// of a 25 px radius: a sharp ball's fits scatter by under 1 %).
    pub odd_radius_share: f64,
    /// A fit whose disc's mean colour lies farther than this many robust scatters
    /// of every fit's from their median, in U or V, and `odd_colour_levels`, is
    /// left out (`tracks::odd_colour`): both balls are alike. Default 6.
    pub odd_colour: f64,
    /// The least such distance, levels. Default 16.
    pub odd_colour_levels: f64,
    /// Such a fit is left out only where at least this many others lie within
    /// `rest_step` radii of it (a thing at rest). Default 3.
    pub odd_colour_still: usize,
    /// The largest deceleration of a ball along the groove, m/s², from which how far
    /// its motion bends away from a straight line between neighbouring fits is
    /// allowed (`tracks::off_the_path`: fits far along the groove from where the
    /// ball's motion puts them are not the ball). Default 10: μ_k 0.5 with a groove
    /// that doubles the normal force.
    pub max_deceleration: f64,
    /// How far along the groove a fit may lie from the smooth motion of its ball's
    /// neighbouring fits (`tracks::off_the_curve`: a parabola through up to
    /// `curve_neighbours` fits either side, on one side of the impact), in robust
    /// scatters of every fit's such distance … Default 6: a fit's own scatter
    /// stays within 3 or 4 of them.
    pub off_the_curve: f64,
    /// … and in shares of the radius, whichever is more. Default 0.1 (2–6 px on the
    /// looks table: a fit's scatter on its hard looks is a pixel or two).
    pub off_the_curve_share: f64,
    /// Fits either side taken for that parabola. Default 3: three a side bend with a
    /// ball's slowing, not with its fits' scatter.
    pub curve_neighbours: usize,
    /// A parabola that misses its own fits by more than this share of what a fit may
    /// lie off it (RMS) judges nothing: the motion there is no parabola (an impact
    /// not told by the closest approach, a ball starting to roll). Default 0.5.
    pub curve_inner: f64,
    /// A ball's fit that lies from the frame before's by under this share of the
    /// ball's motion a frame repeats that frame's picture (`repeats`: a phone's
    /// duplicated frame, a compressed clip's B frame that codes nothing). Default
    /// 0.25: a fit's own scatter is a pixel or two where the ball moves several.
    pub repeat_still: f64,
    /// … judged only where the ball moves at least this many px a frame either
    /// side. Default 2: a ball at rest repeats its place by right.
    pub repeat_speed: f64,
    /// … its motion measured over this many frames either side. Default 8.
    pub repeat_window: usize,
    /// Where the ball turns, slows or meets the impact, a run of fits of one place
    /// repeats one picture when the parabola through the fits about it steps by at
    /// least this many px between each two of its frames (`repeats::turning`); a
    /// fit alone is judged a neighbour's picture only where that parabola steps by
    /// this much at it (`repeats::lone_copies`).
    /// Default 2, as `repeat_speed`: the heavily compressed looks' B frames copy
    /// their reference's picture where the ball turns (the looks table's seed 11:
    /// three fits of one place, 7.3 and 4.7 px off either side of the one of its
    /// own frame); at 1.5 px, two fits of small look 27 a pixel off either way
    /// (about 1.3 and 0.5 px) passed for a run where its ball moved 1.6 px.
    pub repeat_turn_step: f64,
    /// Least share of a luma blob's upper half that differs from the background for
    /// the blob to be taken as a ball. Default 0.15: a ball that moved gives about a
    /// half or more, a still disc of the bench about none. The follower's fit where
    /// it predicts the ball moved on needs as much of its upper half to differ,
    /// unless it is a sharp arc of the balls' radius (`min_coverage_sharp`).
    pub moved_share: f64,
    /// A slot whose last two fits lie within this share of a radius of each other
    /// predicts its ball at rest (`Tracker::moved_off_rest`), and where its ball's
    /// blob lies off that rest, the ball is sought about the blob too. Default 0.1.
    pub rest_step: f64,
    /// … and a blob whose guess lies more than this share of a radius, and more
    /// than `rest_bands` search bands, from that prediction along the picture's
    /// rows is sought about its own guess too. Default 0.25 and 2: a blob's guess is
    /// a coarse pixel or two off (its band). Measured before the tell of
    /// `rest_differ`: at a quarter radius alone, small balls' blobs (full look 108,
    /// R 12 px) were sought off their ball and the clip refused for its radii's
    /// scatter; at one band, full look 10's left ball was held off its turn (centre
    /// RMS 1.67 → 2.58 px).
    pub rest_left: f64,
    /// … see `rest_left`.
    pub rest_bands: f64,
    /// … and that outline kept where its upper half differs from the background
    /// (`Tracker::differing`) over this share more of it than the outline about the
    /// prediction's does. Default 0.05: taken whatever it differs, a moving
    /// shadow's blob took the ball's place (full look 35: 30 px off in three
    /// frames).
    pub rest_differ: f64,
    /// Marks looked at before their sign (darker or lighter than the ball) is
    /// settled. Default 9: a highlight of the other sign in a few of the first
    /// frames is outvoted.
    pub mark_votes: usize,
    /// Most bytes of the patches kept about the fits for the balls' stacked
    /// pictures (`stack`), which measure the radius where the frames' radii
    /// disagree and check it where they agree. Default 96 MiB: a 1080p clip's 300
    /// frames of two balls of 60 px; a clip needing more keeps every second
    /// frame's (and so on), enough for the check, and is not restacked (its
    /// refusal stands).
    pub stack_bytes: usize,
    /// How far a stacked picture's outline lies inside its ball, a share of the
    /// radius, and the ± of that: the outlines lay 3–12 % inside the drawn balls on
    /// the looks table (a limb shaded toward the wall's level: the step's middle
    /// lies inside the ball's edge), which no picture shows apart. The radius is
    /// taken this much larger than the outline's, its standard error at least
    /// this much of it. Default 0.05.
    pub stack_edge: f64,
    /// Most a stacked picture's outline may scatter about its circle, px, for the
    /// picture to give the balls' radius (`Tracker::restacked`). Default 1.25: a
    /// ball of 12 px stacked from 270p frames has an outline a few pixels of h264
    /// blur wide, whose points scatter 0.9–1.1 px (small look 10's two pictures:
    /// 0.88 and 1.09 px, radii 2 and 4 % under its balls', within `stack_edge`);
    /// over 1 px (a frame's outline's `max_rms`) its second picture was not taken
    /// and the clip was refused. No other look's row changed.
    pub stack_max_rms: f64,
    /// Least radius, px, of the outline in colour that is taken for a coloured
    /// ball of the wall's brightness where its outline in brightness is not a
    /// ball's (`Tracker::coloured_in_colour`). Default 20: the colour planes are
    /// half size, 10 samples across such a radius. Full looks 43 and 67 (29.7 and
    /// 38.7 px) were tracked so; on the small looks (balls of 11–16 px) outlines in
    /// colour took small look 5 to a scale 10.7 of its ± off. Not on frames under
    /// 640 px wide (the background learned at full resolution): there, at 20 px,
    /// circles about small look 5's checker squares took its first locks.
    pub colour_own_radius: f64,
    /// Once the balls' radius is known, a coloured ball's outline in colour is
    /// taken where its outline in brightness is not a ball's, whatever the ball's
    /// brightness against the wall, when the outline in colour scatters by at most
    /// this many px RMS about its circle and is a ball's (as `colour_own_radius`
    /// asks: its radius, on frames 640 px wide or more); 0 never. Default 1.0 (a
    /// clear outline's `max_rms`): full look 33 (magenta balls of 27.6 px on a
    /// checker of their brightness under uneven light, 480p at crf 32) differs from
    /// the wall about it by 17–22 levels in brightness in places, so it was not "of
    /// the wall's brightness", and its outlines in brightness scattered 1.1–1.4 px
    /// through the checker's edges: neither ball found in a third of its frames.
    /// Its outlines in colour scatter 0.8–1.1 px within a pixel of the truth. At
    /// any scatter a shaped outline in colour allows (2 px) full look 1 went to a
    /// μ_k 0.016 low; before the radius is known, full looks 38 and 39 lost their
    /// first locks.
    pub colour_over_poor_rms: f64,
    /// Once the balls' radius is known, a coloured ball whose outline in brightness
    /// is a ball's and of that radius within this share of it is not sought in
    /// colour (`Tracker::coloured_in_colour`); 0 seeks it on every fit. The outline
    /// in colour replaces one in brightness only where their radii lie farther apart
    /// than `outer_agree` (10 %), and where the brightness outline is the balls' own
    /// to 1 % the colour outline is then off the radius itself (the colour fading
    /// into a shaded limb: 0.85–0.9 R where taken so on the looks table; small
    /// look 71's fits, 0.72 px RMS off the truth with them, 0.075 px without). On
    /// look 85's 3 s clip, 780 of its 1526 searches in colour were of such outlines
    /// (all within 1 %): its tracks byte for byte, its time 0.93 of before.
    /// Default 0.01: both looks tables' counts and centre RMS as with 0; at 0.05
    /// small look 18 (glossy balls of 11 px, crf 40), refused at 0.01, gives a
    /// scale 4.3 of its ± off.
    pub colour_settled: f64,
    /// A blob of the frame that stays put (its guess within a pixel) and whose own
    /// fit was left out for this many frames running is not fitted but every 16th
    /// frame (left out for the reason it last was); where besides no fit of the
    /// frame lay inside it for as many frames, neither is it searched by Hough. 0
    /// fits and searches every blob in every frame. Default 8: look 85's balls rest
    /// in contact from frame 272 over a wide blob fitted afresh, and failing, in
    /// each of its last 449 frames (6.7–9.8 outline fits a frame for 2.9 while they
    /// moved); from frame 498 Hough or the follower find both balls inside it
    /// (left out as touching) while its own fit fails on, 4 ms a frame (tracker 52).
    /// Balls found touching in the same places (within half a pixel) for as many
    /// frames running, the frame's blobs staying put, are taken as touching
    /// without a fit but every 16th frame (tracker 53: look 85's last 223 frames
    /// each fitted both, 1.4 ms a frame, to leave them out).
    pub stale_blob: usize,
    /// Most the balls' fitted radius may exceed their stacked pictures'
    /// (`Tracker::picture_radii`), as a ratio. Default 1.18: the pictures'
    /// outlines lay up to 15 % inside the drawn balls on the looks table (a limb
    /// shaded toward the wall's level), the fitted radii at most 6 % over them
    /// where the scale came out right; small look 5's frames took in the dark
    /// squares of its checkered wall in every frame, 1.25 over (a scale 22 % large
    /// at ± 3 %). A radius under a picture's is not judged: a picture stacked at
    /// the fits' centres can keep a blur of the wall's pattern about the ball
    /// (small look 1's white ball on a light checker: 17.4 px for 14.3).
    pub picture_ratio: f64,
    /// Largest scatter of the fitted radii (robust, a share of their median) that
    /// still gives a scale. Default 0.05: a sharp ball's radius scatters by under
    /// 1 %, a blurred one's by a few; both balls have one radius.
    pub max_radius_spread: f64,
    /// Whether each outline is sought first in the frame's difference from the
    /// background once the balls' radius is known (`Tracker::difference_outline`),
    /// the frame's own outline where it gives none. Default false: the clip is
    /// tracked so again only where its frames' radii disagree
    /// (`input::video::tracked`), as the difference's outline takes in a shadow or
    /// a compression fringe that differs as much as the ball (the looks table, taken
    /// first on every clip: two μ_k wrong of 80).
    pub difference_first: bool,
    /// Whether a grey ball of any brightness (steel, white), not only a dark one
    /// (`dark_ball`), whose outline in brightness is poor is sought in colour, where
    /// the wall about it is of one colour (`tracker::wall_of_one_colour`). Default
    /// false: a clip is tracked so again only where neither ball was found in a
    /// third of its frames (`input::video::tracked`); taken first on every clip, a
    /// grey ball's outline in colour moved the centres of tracked looks by up to
    /// 6 px (BENCHMARKS.md), and on a checkered or striped wall it took in the
    /// wall's squares (full look 15: a radius 12 % large).
    pub grey_in_colour: bool,
    /// Clear outlines (`min_coverage`, `max_rms`, over a rail) left out for their
    /// radius alone, at least this many and more than the fits kept, that agree on a
    /// radius within `max_radius_spread` (1.4826 × their median absolute deviation),
    /// contradict the radius learned: the clip is tracked again at theirs
    /// ([`super::Tracker::radius_contradicted`]). Default 10: a ball seen for a
    /// third of a second at 30 frames/s.
    pub min_contradicting: usize,
    /// A ball must be found in at least one in this many frames for tracks to be
    /// given. Default 3: found more rarely, what was found may be something else (a
    /// mark, a highlight) in the frames where the ball itself was missed.
    pub sparsest: usize,
    /// Fewest frames a ball must be seen in to be one (not a passing blob), and
    /// fewest frames a clip must have. Default 3.
    pub fewest_seen: usize,
    /// How uncertain the place of a ball's edge is at least, px, whatever the number
    /// of frames; carried into the radius and so the scale. Default 0.2: the
    /// gradient's peak sits inside the outline where the ball's shading falls into
    /// its limb (the project's plain renders: 0.02 px for a flat ball, 0.06 px for a
    /// shaded one), and on the full looks (walls of texture, uneven light,
    /// compression) large balls lay farther in, whatever their radius: 0.24–0.30 px
    /// at R 39–69 px, with a ± of 0.11–0.15 px by the other terms (three scales
    /// beyond 2 ± at 0.05 px). Over the 94 full looks with a radius the fit lies 0.05 px
    /// inside on average, over the 124 small ones 0.11 px. At 0.2 px no full look
    /// lies beyond 2 ± (the worst 1.7), and the scales beyond their ± are 13 of 93
    /// (17 at 0.05), on the small looks 18 of 118 (20; their `edge_lean` is most
    /// often more already).
    pub edge_systematic: f64,
    /// How far the ball's edge may lean toward the darker side at least, px, is this
    /// (px²) over the balls' radius in px; carried into the radius's ± (a lean every
    /// frame shares, which the frames' scatter does not show). A ball is shaded,
    /// darker toward its limb; blurred (σ px), that ramp inside the step moves the
    /// gradient's peak by about its slope × σ² over the step, inward on a light ball
    /// on a dark wall, outward on a dark ball on a light one, and the slope falls
    /// with the radius: a lean of some σ²/R. Default 3: the small looks (R 11–17 px)
    /// lay 0.1–0.35 px off so (three scales beyond 2 ± without it, 3/13 = 0.23 px),
    /// the full looks' (R 23–66 px) within their ± already.
    pub edge_lean: f64,
    /// How much a near rail's straight edge must move a circle's radius, as a share
    /// of it, for the circle to be fitted again without the edge (`circle::fit`): a
    /// rail's top or lower edge, running on past the ball both ways, closes a sunk
    /// ball's visible cap into a smaller circle or is taken into a larger one.
    /// Default 0.05 (the radii's spread that refuses a clip, `max_radius_spread`):
    /// the small looks' seeds 48 and 87 lay 26 % and 41 % off so; a smaller move is
    /// the edge's own scatter, and the fit with the edge's points is kept. Infinite:
    /// never refitted.
    pub rail_moves: f64,
    /// How far outside the circle the rest of a ball's edge points give its cast
    /// shadow's edge points lie, px (their median), for them to be left out
    /// (`circle::fit_keeping`; a point is the shadow's where its inside is the wall
    /// in shadow, `tracker::in_the_walls_shadow`). Default 1.5: past a blurred
    /// edge's own scatter; small looks 135 and 156 (steel balls of 14 px beside
    /// shadows a quarter of a radius out), 3–6 px. Infinite: never left out.
    pub shadow_outside: f64,
    /// The ball's edge in colour (`circle::colour_offset`): sought between this many
    /// px inside and outside the outline (default 5: a lit part of a dozen-pixel
    /// ball lies 3–4 px inside its edge), where the colour there differs by at least
    /// `colour_edge_step` levels (default 12, U and V together: a clear step of hue,
    /// not the codec's noise). Where its median place over the frames lies farther
    /// than `colour_edge_within` px from the outline (default 1: a pixel of the
    /// half-size colour planes, whose edge is no sharper), the outline is in doubt
    /// by that much, and the radius's ± takes it in.
    pub colour_edge_reach: f64,
    pub colour_edge_step: f64,
    pub colour_edge_within: f64,
}

/// The thresholds that tell a ball's drawn mark from a highlight, a spot of the wall
/// or a mark that jumps ([`super::mark_check`]); lengths in the ball's radii unless
/// said.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MarkChecks {
    /// Two spots of a disc this near are one spot. Default 0.08.
    pub same_spot: f64,
    /// A place of the disc where a spot stands out in at least this share of each
    /// ball's frames is a highlight or a feature of the shading, not a mark (a
    /// drawn mark turns with its ball and passes any one place in a few frames).
    /// Default 0.7 (a highlight is found in 0.9–1 of them; a drawn mark that comes
    /// back to a place every few frames, in a third or less) …
    pub fixed_present: f64,
    /// … and marks found within this of it are not taken (the highlight or the
    /// mark overlapping it: a centroid of both). Default 0.25: a quarter of a
    /// radius, a mark's radius (0.1–0.2) and the highlight's.
    pub spot_reach: f64,
    /// A mark standing out from its ball by less than this share of the contrast
    /// both balls' marks have (their median) is not the drawn mark (a drawn mark
    /// keeps its colour; the shading near the limb or the fringe about a highlight,
    /// found where the mark is hidden, stand out faintly). Default 0.5.
    pub faint_share: f64,
    /// A mark is unsure when another spot of its sign in the disc (not a highlight's
    /// fixed place), a quarter of a radius or more away, stands out by more than
    /// 1 / this of the mark's own contrast: two spots alike, no telling which is
    /// drawn. Default 1.5 (a drawn mark stands out by 2–10 times what the shading, a
    /// highlight's fringe or compression leave).
    pub rival_ratio: f64,
    /// Share of a ball's marks at one spot of its disc that makes the spot a
    /// highlight, when the ball moved by at least `rolled` radii meanwhile (a mark
    /// on a ball that rolls one radius turns by one radian, and even a ball sliding
    /// after the impact turns by half that over its sliding). Default 0.6 …
    pub fixed_share: f64,
    /// … and that move, radii. Default 2.
    pub rolled: f64,
    /// A mark that moves less than this share of its ball's move between two frames
    /// stays put in the picture: a spot of the wall (a mark on a rolling ball moves
    /// at a third of the ball's speed or more where it can be seen, above the rail).
    /// Default 0.15 …
    pub still_share: f64,
    /// … told only where the ball moved this far, px. Default 2.
    pub moved_px: f64,
    /// How far a mark may lie from the circle its ball's marks keep to: a drawn mark
    /// stays at one distance from the centre as the ball turns (the fit of the
    /// spot's centroid moves it by a few hundredths of a radius). Default 0.12.
    pub on_circle: f64,
    /// Share of a ball's marks that must keep to one circle about the centre for
    /// them to be a drawn mark's (not a highlight here, a wall's spot there, the
    /// rail's edge). Default 0.6.
    pub kept_share: f64,
    /// Fewest marks of a ball from which their circle and their turning are told.
    /// Default 5.
    pub fewest_marks: usize,
    /// Largest turn of a drawn mark per rolling radius its ball moves (a ball rolling
    /// on the rails' edges, kR below its centre, turns by Δx / (kR): the rail's top
    /// is the lowest point of the outline; 1.6 leaves room for the centroid's and
    /// the centre's errors). Default 1.6 …
    pub turn_per_radius: f64,
    /// … and the turn allowed whatever the move, rad (noise on a mark at half the
    /// radius). Default 0.35.
    pub turn_slack: f64,
    /// Share of the steps between a ball's marked frames that may turn faster than
    /// rolling allows before its marks are taken for something else (a spot that
    /// jumps between the mark, a highlight and the wall). Default 0.2.
    pub jumps_share: f64,
    /// Roll (rad, the ball's move over its radius, summed between marked frames)
    /// from which a mark that does not turn is told from one that does. Default 1.5 …
    pub min_roll: f64,
    /// … and the least share of that roll a drawn mark turns by (a struck ball
    /// slides with its spin growing from none; over a clip with rolling in it, a
    /// third or more). Default 0.3.
    pub least_turn_share: f64,
    /// Marks of one ball found at one place of its disc (within `stay_within`
    /// radii) frame after frame, while the ball moved on by a roll (its move over kR,
    /// rad) of at least this, are no drawn mark, all left out: a ball that rolls
    /// turns, and even a struck ball that slides without spin at first turns by
    /// half a radian or more before it has rolled 2 rad (its spin grows from none
    /// over a sliding phase of about 3 rad at μ_k 0.17). What stays is the
    /// compression's blocks on the upper limb, a highlight, the shading's darkest
    /// spot. "Frame after frame": each at most as many frames after the one before
    /// as the ball's fast roll (its 80th percentile per frame, 1.5 times over)
    /// needs for half a turn, so that a drawn mark cannot have come round meanwhile.
    /// Default 2 …
    pub stay_roll: f64,
    /// … and "one place" is within this many radii. Default 0.12 (a fixed spot's
    /// centroid wanders by under 0.1 R; a sliding ball's mark that turned by half a
    /// radian, at 0.4–0.7 R, has moved 0.2 R or more).
    pub stay_within: f64,
    /// A mark needs a mark of its ball at most this many frames away that agrees
    /// with it (turned by no more than rolling allows, `turn_per_radius`,
    /// `turn_slack`) wherever such a step can be judged (the ball rolled less than a
    /// quarter turn): a lone spot found where the drawn mark is hidden (behind the
    /// rail), or a compressed clip's trace of the mark of the frame before, agrees
    /// with neither neighbour. Default 2.
    pub confirm_frames: usize,
    /// A mark must lie where its ball's spin puts it, wherever that spin is told by
    /// two marks of the ball a frame or two apart (a step of under a quarter turn of
    /// roll, so the turn between them is read without a whole turn's doubt) at most
    /// this many frames from it: the angle carried on from either at their rate of
    /// turning. A ball's spin changes slowly (friction on the rails; an impact of two
    /// balls leaves it as it was), so a spot elsewhere on the disc is something else:
    /// a spot that turns up where the mark was a whole turn ago, at a fast ball's
    /// rate of a turn every few frames, agrees with every neighbour too far off to be
    /// judged by `confirm_frames`. Default 4 …
    pub spin_frames: usize,
    /// … within this many radians … Default 0.6 …
    pub spin_slack: f64,
    /// … and this many more per frame from the nearer of the two (the rate read off
    /// two noisy angles, and friction changing it). Default 0.15.
    pub spin_drift: f64,
    /// Two marks of a ball in consecutive frames whose place in the disc turned by
    /// under this share of what the ball's spin (its marks' net turn a frame about
    /// them, [`MarkChecks::repeat_frames`] each way) turns a drawn mark in a frame
    /// show one picture twice (a compressed clip's frame that repeats, or blends in,
    /// another's), and neither is told to be its own frame's: both left out.
    /// Default 0.5 …
    pub repeat_share: f64,
    /// … judged where that spin moves the mark by this many px a frame or more.
    /// Default 1.5 …
    pub repeat_px: f64,
    /// … the spin read over this many frames either way. Default 8.
    pub repeat_frames: usize,
}

impl Default for MarkChecks {
    fn default() -> Self {
        MarkChecks {
            same_spot: 0.08,
            fixed_present: 0.7,
            spot_reach: 0.25,
            faint_share: 0.5,
            rival_ratio: 1.5,
            fixed_share: 0.6,
            rolled: 2.0,
            still_share: 0.15,
            moved_px: 2.0,
            on_circle: 0.12,
            kept_share: 0.6,
            fewest_marks: 5,
            turn_per_radius: 1.6,
            turn_slack: 0.35,
            jumps_share: 0.2,
            min_roll: 1.5,
            least_turn_share: 0.3,
            stay_roll: 2.0,
            stay_within: 0.12,
            confirm_frames: 2,
            spin_frames: 4,
            spin_slack: 0.6,
            spin_drift: 0.15,
            repeat_share: 0.5,
            repeat_px: 1.5,
            repeat_frames: 8,
        }
    }
}

impl Default for Params {
    fn default() -> Self {
        Params {
            roi: None,
            ball_at: None,
            radius_px: None,
            min_radius: 8.0,
            coarse_width: 320,
            background_frames: 48,
            differ_sigmas: 5.0,
            differ_levels: 10.0,
            faint_levels: 6.0,
            colour_weight: 2.0,
            shadow_darkest: 0.5,
            shadow_hue_levels: 6.0,
            min_coverage: 0.35,
            min_coverage_known: 0.28,
            min_coverage_sharp: 0.19,
            rail_view_deg: 20.0,
            sharp_rms: 0.25,
            sharp_radius: 0.03,
            max_rms: 1.0,
            radius_tolerance: 0.15,
            smallest_in_blob: 0.6,
            fringe_share: 0.125,
            core_first: 0.8,
            outer_reach: 2.2,
            outer_step: 10.0,
            outer_margin: 2.0,
            outer_agree: 0.1,
            window_radii: 0.5,
            touch_gap: 2.0,
            max_across: 0.15,
            least_travel: 0.25,
            mark_sigmas: 6.0,
            mark_levels: 10.0,
            mark_cut: 0.3,
            mark_soft: 1.4,
            wide_blob: 1.3,
            part_width: 0.75,
            dark_ball: 64.0,
            grey_levels: 6.0,
            colour_clear_rms: 0.7,
            locks_agree: 0.15,
            confirm_spread: 0.05,
            hough_arc: 0.2,
            marks: MarkChecks::default(),
            off_the_line: 0.25,
            odd_radius: 3.0,
            odd_radius_share: 0.02,
            odd_colour: 6.0,
            odd_colour_levels: 16.0,
            odd_colour_still: 3,
            max_deceleration: 10.0,
            off_the_curve: 6.0,
            off_the_curve_share: 0.1,
            curve_neighbours: 3,
            curve_inner: 0.5,
            repeat_still: 0.25,
            repeat_speed: 2.0,
            repeat_window: 8,
            repeat_turn_step: 2.0,
            moved_share: 0.15,
            rest_step: 0.1,
            rest_left: 0.25,
            rest_bands: 2.0,
            rest_differ: 0.05,
            mark_votes: 9,
            stack_bytes: 96 << 20,
            stack_edge: 0.05,
            stack_max_rms: 1.25,
            colour_own_radius: 20.0,
            colour_over_poor_rms: 1.0,
            colour_settled: 0.01,
            stale_blob: 8,
            picture_ratio: 1.18,
            max_radius_spread: 0.05,
            difference_first: false,
            grey_in_colour: false,
            min_contradicting: 10,
            sparsest: 3,
            fewest_seen: 3,
            edge_systematic: 0.2,
            edge_lean: 3.0,
            rail_moves: 0.05,
            shadow_outside: 1.5,
            colour_edge_reach: 6.0,
            colour_edge_step: 12.0,
            colour_edge_within: 1.0,
        }
    }
}
