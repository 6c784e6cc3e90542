# pipelens: the interface in English, the fallback for every other language.
# One message per word or phrase the interface shows; grouped by the source file that shows it.

language-name = English

## src/app/chrome.rs

chrome-help-keyboard-shortcuts = Help: keyboard shortcuts
chrome-keyboard-shortcuts-f1 = Keyboard shortcuts (F1)
chrome-switch-the-language = Switch the language
chrome-classroom = Classroom
chrome-large-type-and-high-contrast = Large type and high contrast for a projector; the picture first (C). F11: full screen, Ctrl +/−: text size, ←/→: steps or stages, Space: play.
chrome-the-file-changed-on-disk = The file changed on disk and no longer loads; the last good version keeps running:
chrome-close-this-message = Close this message
chrome-close-the-keyboard-shortcuts = Close the keyboard shortcuts (F1)
chrome-previous-step = Previous step
chrome-previous-step-or-page-up = Previous step (← or Page Up)
chrome-step = Step
chrome-next-step = Next step
chrome-next-step-or-page-down = Next step (→ or Page Down)
chrome-pause = ‖ Pause
chrome-play = ▶ Play
chrome-play-or-pause-the-animation = Play or pause the animation (Space)
chrome-narration = Narration
chrome-show-or-fold-the-narration = Show or fold the narration over the picture (N)
chrome-parameters = Parameters
chrome-the-camera-projection-rasterizer-and = The camera, projection, rasterizer and objects (P)
chrome-inspector = Inspector
chrome-matrices-the-vertex-table-the = Matrices, the vertex table, the pixel inspector (I)
chrome-matrix = Matrix
chrome-the-stage-s-matrix-over = The stage's matrix over the geometry (M)
chrome-shader = Shader
chrome-write-the-vertex-and-fragment = Write the vertex and fragment shaders in GLSL; Ctrl+Enter applies (S)
chrome-show = Show ▾
chrome-download-handout = Download handout
chrome-the-lesson-s-handout-in = The lesson's handout in this language as one HTML file, every image in it, printable (it takes a few seconds to render every step). Snapshots of every buffer: the desktop app or `pipelens export`.
chrome-download-my-work = Download my work
chrome-one-file-with-this-lesson = One file with this lesson's code you last ran at each step and the answers you typed (LESSON-work.toml): hand it in; a teacher grades it with `pipelens grade LESSON FILE`.
chrome-export = Export ▾
chrome-folder = Folder
chrome-the-folder-the-snapshot-is = The folder the snapshot is written to (created if missing).
chrome-export-snapshot = Export snapshot
chrome-every-buffer-as-png-and = Every buffer as PNG and capture.json, as `pipelens export` writes them.
chrome-export-handout-and-slides = Export handout and slides
chrome-the-lesson-s-handout-in-2 = The lesson's handout in this language (index.html, every image in it, printable) and one 1920×1080 slide per step (slides/), as `pipelens export LESSON --slides` writes them.
chrome-export-my-work = Export my work
chrome-one-file-with-this-lesson-2 = One file with this lesson's code you last ran at each step and the answers you typed (LESSON-work.toml, into the folder above): hand it in; a teacher grades it with `pipelens grade LESSON FILE`.
chrome-cancel-export = Cancel export
chrome-stops-between-two-files-those = Stops between two files: those written stay whole.
chrome-error = Error: { $message }
chrome-showing-the-last-good-frame = (showing the last good frame)
chrome-triangles = triangles
chrome-frame = frame
chrome-vertex = vertex
chrome-clip = clip
chrome-raster = raster
chrome-resolve = resolve
chrome-keyboard-shortcuts = Keyboard shortcuts
chrome-triangles-dropped-gl-position-nan = triangles dropped: gl_Position NaN or ∞
chrome-a-vertex-shader-wrote-a = A vertex shader wrote a gl_Position that is not a finite number (a division by zero, normalize(vec3(0.0))): nothing can be drawn from it, so its triangles are dropped before clipping. The Vertices tab shows the vertex's run.
chrome-fragments-shaded = fragments shaded
chrome-discarded = discarded
chrome-the-fragment-shader-ran-once = The fragment shader ran once per fragment (2×2 quads' helper lanes not counted); `discard` threw these away.
chrome-pixels-nan-or-drawn-black = pixels NaN or ∞ (drawn black)
chrome-a-shader-s-colour-was = A shader's colour was not a finite number, e.g. normalize(vec3(0.0)) or 0.0/0.0: click such a pixel to see the statement that made it.

## src/app/compact.rs

compact-menu = Menu
compact-keys = Keys (?)
compact-stage = Stage
compact-picture = Picture
compact-code = Code

## src/app/editor/file.rs

file-cannot-read = cannot read { $file }: { $why }
file-not-saved = not saved: { $why }
file-changed-since-opened = { $file } changed on disk since it was opened: overwrite it, or load it and lose these edits?
file-no-file = no file
file-no-text-to-edit = { $source }: no text to edit

## src/app/editor/file_actions.rs

file-actions-undo = ↶ Undo
file-actions-redo = ↷ Redo
file-actions-save-as-a-new-lesson = Save as a new lesson ↓
file-actions-save = Save
file-actions-save-download = Save (download)
file-actions-a-built-in-lesson-is = A built-in lesson is not changed: make it a lesson file of your own below (New lesson, from this lesson).
file-actions-ctrl-s-the-file-is = Ctrl+S: the file is written whole or not at all
file-actions-unsaved = ● unsaved
file-actions-unsaved-changes-kept-in-a = Unsaved changes, kept in a recovery copy beside the file until saved (Ctrl+S).
file-actions-saved = saved
file-actions-unsaved-changes-to-this-lesson = Unsaved changes to this lesson were kept from the last time it was edited.
file-actions-restore-them = Restore them
file-actions-restored-save-keeps-them-undo = Restored: Save keeps them, Undo drops them.
file-actions-discard-them = Discard them
file-actions-the-file-changed-on-disk = The file changed on disk while you were editing it.
file-actions-overwrite-it-with-my-edits = Overwrite it with my edits
file-actions-load-it-from-disk-undo = Load it from disk (Undo brings my edits back)
file-actions-loaded-from-disk = Loaded from disk.
file-actions-saved-to = Saved: { $file }
file-actions-not-done-the-lesson-would = Not done: the lesson would no longer pass the check (a step's parameters may need one before it):
file-actions-the-lesson-does-not-pass = The lesson does not pass the check; the last good version keeps playing until this is fixed:

## src/app/editor/new.rs

new-new-lesson = New lesson…
new-from-the-scene-on-screen = from the scene on screen, with this view as its first step
new-from-a-built-in-lesson = from a built-in lesson:
new-from-a-mesh-of-your = from a mesh of your own (.obj; or drop one on the window):
new-write-it-to = Write it to:
new-name = Name:
new-make-the-lesson = Make the lesson
new-nothing-on-screen = nothing on screen to start from
new-choose-a-built-in-lesson = choose a built-in lesson
new-name-the-mesh-file = name the mesh file (.obj)
new-from-a-mesh-dropped = from a mesh dropped on the page (.obj):
new-drop-the-mesh = drop the mesh (.obj) on the page first
new-exists-already = { $file } exists already: choose another name (it was left as it is)
new-cannot-create = cannot create { $dir }: { $why }
new-made = New lesson: { $source }
new-no-lesson-open = no lesson open

## src/app/editor/screen.rs

screen-update-step = Update step { $step } from the screen
screen-new-step-words = A new step { $step }: its words
screen-add-as-step = ＋ Add as step { $step }
screen-what-is-on-screen = What is on screen
screen-the-stage-buffer-layout-overlays = The stage, buffer, layout, overlays, inspected pixel, selected vertex and every parameter changed since this step began. Drag a slider while the editor is open to record an animation.
screen-no-parameter-changed = No parameter changed.
screen-its-words-shaders-and-exercise = Its words, shaders and exercise are kept
screen-title = Title
screen-narration = Narration
screen-seconds-from-the-first-value = Seconds from the first value to the last
screen-not-an-animation = Not an animation

## src/app/editor/window.rs

window-steps-deleted = { $count ->
    [one] 1 step deleted since the last save
   *[other] { $count } steps deleted since the last save
}
window-step-label = Step { $step }:
window-lesson-editor = Lesson editor
window-close-the-editor-r = Close the editor (R)
window-a-built-in-lesson-is = A built-in lesson is not edited in place. Make it a lesson of your own (New lesson, from this lesson, below), then record, word and arrange its steps there.
window-open-a-lesson-to-edit = Open a lesson to edit it, or make a new one below.
window-steps = Steps
window-changed-since-the-last-save = ● changed since the last save
window-earlier = ▲ Earlier
window-later = ▼ Later
window-duplicate = Duplicate
window-delete = Delete

## src/app/editor/words.rs

words-of-step = The words of step { $step }
words-the-lesson-s-title-and = The lesson's title and summary
words-title = Title
words-summary = Summary
words-narration = Narration
words-question-optional = Question (optional)
words-answer-optional = Answer (optional)
words-worded-english = Worded: English, 中文
words-still-needs = Still needs:

## src/app/export_task.rs

export-task-handout-saved = Handout saved: { $file }
export-task-exported-to = Exported to { $dir }: { $files }
export-task-your-work-saved = Your work saved: { $file } ({ $steps ->
        [one] 1 step with work
       *[other] { $steps } steps with work
    })

## src/app/platform.rs

platform-the-browser-refused-the-download = the browser refused the download: { $why }

## src/app/layout.rs

layout-resize-panel = Resize panel: { $panel }

## src/app/library.rs

library-could-not-be-opened = { $file } could not be opened; what was open keeps running:
library-not-a-kind-pipelens-opens = { $name }: pipelens opens lessons and scenes (.toml), shaders (.vert, .frag, .glsl), meshes (.obj) and textures (.png, .jpg), not .{ $extension } files
library-not-text = the file is not UTF-8 text: drop a lesson or scene .toml file
library-shader-not-text = { $name } is not UTF-8 text
library-a-texture-on-the-desktop = { $name }: a texture is read by the lesson that names it (texture = "{ $name }"), from the lesson's folder: open that lesson instead
library-texture-kept = { $name } is kept for the lessons that name it (texture = "{ $name }"): drop such a lesson now, or a lesson and its textures together.
library-cannot-read-the-file = cannot read the file: { $why }
library-lessons = Lessons
library-all-right = all right
library-d-n-questions-you-answered = d/n: questions you answered right, of those with a value to type
library-edit-this-lesson-or-make = Edit this lesson, or make one… (R)
library-record-what-is-on-screen = Record what is on screen as steps, word them in both languages, arrange them, save the file
library-your-own-lesson-or-scene = Your own lesson or scene: drop its .toml file on the window; it reloads when you save it.
library-your-own-lesson-or-scene-2 = Your own lesson or scene: drop its .toml file on the page, with the meshes (.obj) and textures (.png, .jpg) it names; a mesh dropped alone becomes a new lesson. A page cannot watch files: after an edit, drop it again.
library-open-another-built-in-lesson = Open another built-in lesson

## src/app/platform.rs

platform-pipelens-the-keys-typed-into = pipelens: the keys typed into the app

## src/app/step_panels.rs

step-panels-shaders-glsl = Shaders (GLSL)

## src/app/toolbar.rs

toolbar-view = View ▾
toolbar-observer-view = Observer view
toolbar-the-scene-seen-from-outside = The scene seen from outside, with the camera's frustum and the lights.
toolbar-side-by-side = side by side
toolbar-off = off
toolbar-render-the-scene-with-different = Render the scene with different settings and show them side by side, with an intensity profile.

## src/app/views/alt.rs

alt-name-colon = :{" "}

## src/app/views/answer.rs

answer-type-the-value = Type the value
answer-type-the-components = Type the { $n } components
answer-type-the-values = Type the { $n } values
answer-type-the-matrix = Type the { $rows }×{ $columns } matrix, cell by cell
answer-prompt = { $what } (each within { $tolerance }):
answer-a-number-or-an-expression = A number or an expression: 0.866, sqrt(3)/2, 2*pi/3, 1/4
answer-check = Check
answer-compare-with-the-expected-value = Compare with the expected value (Enter)
answer-answered-right-before = answered right before

## src/app/views/breakpoints.rs

breakpoints-line = line
breakpoints-at-hit = at hit
breakpoints-every = every
breakpoints-stop-only-the-n-th = Stop only the n-th time the run reaches this line (in a loop: its n-th iteration); 0 stops at every hit.
breakpoints-where = where
breakpoints-find-in-the-frame = Find in the frame
breakpoints-the-first-fragment-reading-the = The first fragment, reading the picture from the top, where the condition holds just after this line: it is inspected, and its run shown at this line.
breakpoints-the-condition-cannot-be-read = The condition cannot be read there:
breakpoints-remove-this-breakpoint = Remove this breakpoint
breakpoints-holds-at-no-fragment-of = holds at no fragment of this frame after that line.
breakpoints-is-not-a-condition-a = is not a condition (a bool): write a comparison, such as diffuse <= 0.0.

## src/app/views/compare.rs

compare-rendering-the-comparison = Rendering the comparison…
compare-compared-image = compared image: { $caption }

## src/app/views/debugger.rs

debugger-this-is-the-run-s = This is the run's first step.
debugger-no-breakpoint-stops-the-run = No breakpoint stops the run before this step.
debugger-no-breakpoint-is-set-click = No breakpoint is set: click a line number, or press F9 on a line.
debugger-no-breakpoint-stops-the-rest = No breakpoint stops the rest of this run.
debugger-put-the-text-cursor-on = Put the text cursor on a line first.
debugger-the-rest-of-this-run = The rest of this run never reaches the cursor's line.
debugger-this-step-is-in-main = This step is in main: there is no caller to return to.
debugger-this-is-the-run-s-2 = This is the run's last step.
debugger-step = step
debugger-line = line
debugger-steps-f10-steps-through-them = steps: F10 steps through them
debugger-watch = watch
debugger-after-line = after line
debugger-variables-at-this-step = Variables at this step
debugger-debugger-click-a-pixel-of = Debugger: click a pixel of the picture; its fragment's run steps here (F10).
debugger-debugger-select-a-vertex-a = Debugger: select a vertex (a click in a geometry view, or a row of the vertex table); its run steps here (F10).
debugger-fragment = fragment
debugger-several-fragments-reached-this-pixel = Several fragments reached this pixel (triangles meeting in it, or layers a discard peeled): which one to follow.

## src/app/views/exercise.rs

list-separator = { ", " }
sentence-separator = { " " }
exercise-drawing-pipelens-own-frame = Drawing pipelens' own frame…
exercise-pipelens-own = pipelens' own
exercise-difference = difference:{ " " }
exercise-colour = colour
exercise-coverage = coverage
exercise-depth = depth
exercise-another-triangle = another triangle
exercise-exercise = Exercise
exercise-write-your-code-in-the = Write your code in the Shader panel (key S): it runs as you type, and your curve is compared with pipelens' b(t), point by point.
exercise-write-your-code-in-the-2 = Write your code in the Shader panel (key S): it runs as you type, and your surface is compared with pipelens' b(u, v), point by point.
exercise-write-your-code-in-the-3 = Write your code in the Shader panel (key S): it runs as you type, and the frame is compared with pipelens' own, pixel by pixel.
exercise-inspect-the-first-wrong-vertex = Inspect the first wrong vertex
exercise-selects-its-row-of-the = Selects its row of the vertex table: the Inspector shows your vertex shader's run for it.
exercise-inspect-the-first-wrong-pixel = Inspect the first wrong pixel
exercise-selects-it-the-inspector-shows = Selects it: the Inspector shows your shader's run there beside pipelens' own derivation.
exercise-passed-before = Passed before.

## src/app/views/geometry/cards.rs

cards-near-plane = near plane
cards-far-plane = far plane
cards-light = light
cards-showing-triangles = showing triangles

## src/app/views/geometry/mod.rs

geometry-geometry-view = geometry view
geometry-nothing-to-show-in-this = nothing to show in this space
geometry-front-view = Front view
geometry-reset-view = Reset view
geometry-or-double-click-the-picture = Or double-click the picture.
geometry-legend = Legend
geometry-legend-what = What the picture's colours and dashes mean: tap to show or hide it.
geometry-normals = Normals
geometry-each-vertex-s-normal-n = Each vertex's normal n in world space, the one lighting uses (n_world = (M^(−1))^T·n).
geometry-replay-transition = ▶ Replay transition
geometry-space = Space

## src/app/views/glsl_keys.rs

code-keys-types = Types { $key } where the cursor is

## src/app/views/inspector/matrices.rs

matrices-what-this-stage-applies = What this stage applies
matrices-games101-s-m-viewport-maps = GAMES101's M_viewport maps x and y the same way and leaves z unchanged; OpenGL (and pipelens) also maps z from [−1, 1] to z_w ∈ [0, 1]. (The notes label this matrix M_{"{"}persp→ortho{"}"} by mistake.)
matrices-other-matrices = Other matrices
matrices-object = object
matrices-the-same-projection-in-games101 = The same projection in GAMES101's terms (n = −near, f = −far):
matrices-m-ortho-m-persp-ortho = M_ortho·M_{"{"}persp→ortho{"}"} = −Z·P with Z = diag(1, 1, −1, 1): the same x, y after the division; NDC z mirrored (near → +1).
matrices-m-ortho-z-ortho-with = M_ortho = Z·Ortho with Z = diag(1, 1, −1, 1): NDC z mirrored (near → +1).
matrices-matrix-stack-depth-first = Matrix stack, depth-first

## src/app/views/inspector/mod.rs

inspector-matrices = Matrices
inspector-vertices = Vertices
inspector-pixel = Pixel

## src/app/views/inspector/pixel.rs

pixel-click-a-pixel-in-a = Click a pixel in a pixel view (Rasterization, Depth, Shading, Texturing, Output) to see every fragment that reached it and how its colour was made.
pixel-pixel = Pixel
pixel-triangle = triangle
pixel-coverage = coverage
pixel-depth-mean-of-samples = depth (mean of samples)
pixel-colour = colour
pixel-how-the-fragment-got-here = How the fragment got here (and what pipelens' own shading would make of it):
pixel-no-fragment-owns-this-pixel = No fragment owns this pixel: it keeps the background.
pixel-every-fragment-that-reached-the = Every fragment that reached the pixel
pixel-none = None.
pixel-your-inside-covers-none-of = Your inside() covers none of these fragments' samples (the samples above are pipelens' own edge test's).
pixel-every-fragment-failed-the-depth = Every fragment failed the depth test.
pixel-explain-this-pixel = Explain this pixel
pixel-fragment = fragment
pixel-visible = {"  "}√ visible
pixel-a-piece-of-a-clipped = (a piece of a clipped triangle)
pixel-samples = samples:
pixel-not-covered = not covered
pixel-covered-passed-the-depth-test = covered, passed the depth test:
pixel-covered-failed-the-depth-test = covered, failed the depth test:
pixel-on-an-edge-the-top = {"*"} on an edge: the top-left rule decided

## src/app/views/inspector/rotation.rs

rotation-the-same-rotation-r-n = The same rotation R(n, θ), two more ways
rotation-rodrigues-formula-n-the-cross = Rodrigues' formula, N the cross-product matrix of n:
rotation-w-x-y-z-q = (w, x, y, z); −q is the same rotation. Its matrix:
rotation-halfway-along-the-shortest-arc = halfway along the shortest arc, the rotation by θ/2 about the same axis.
rotation-between-two-orientations-slerp = Between two orientations: slerp
rotation-the-first-axis = the first axis
rotation-the-second-axis = the second axis
rotation-0-slerp-takes-q-the = {" "}< 0: slerp takes −q₁, the same rotation, the shorter way round
rotation-the-turn-from-one-to = the turn from one to the other
rotation-weights = weights
rotation-about = about

## src/app/views/inspector/shader_trace.rs

shader-trace-your-fragment-shader-at-this = Your fragment shader at this pixel
shader-trace-it-did-not-run-here = It did not run here: no triangle of an object with shaders covers this pixel.
shader-trace-pixels-of-this-frame-came = pixels of this frame came out NaN or infinite (drawn black).
shader-trace-fragment = fragment
shader-trace-triangle = triangle
shader-trace-sample-s = sample(s)
shader-trace-received-interpolated-across-the-triangle = received (interpolated across the triangle)
shader-trace-ran-statement-by-statement = ran, statement by statement
shader-trace-discarded-what-lies-behind-shows = → discarded: what lies behind shows instead.
shader-trace-your-vertex-shader-at-vertex = Your vertex shader at vertex
shader-trace-received-its-attributes = received (its attributes)
shader-trace-wrote = wrote
shader-trace-line = line

## src/app/views/inspector/vertices.rs

vertices-model = model
vertices-world = world
vertices-eye = eye
vertices-clip-x-y-z-w = clip (x, y, z, w)
vertices-window = window
vertices-spaces = spaces:
vertices-click-a-row-to-highlight = Click a row to highlight the vertex in every view; click a vertex in a view to find its row.
vertices-vertex = vertex
vertices-object = object

## src/app/views/lesson.rs

lesson-fold-the-narration-away = Fold the narration away
lesson-fold-the-narration-away-n = Fold the narration away (N)
lesson-predict-first-the-question-below = Predict first (the question below), then press Space to watch.
lesson-animation-line = ▶ { $param }: { $from } → { $to }
lesson-question = Question
lesson-hide-the-answer = Hide the answer
lesson-show-the-answer = Show the answer

## src/app/views/matrix.rs

matrix-grid = the 4×4 matrix, row by row: { $rows }
matrix-grid-row = row { $row }: { $values }
matrix-factors = Factors

## src/app/views/observer.rs

observer-observer-the-scene-seen-from = observer: the scene seen from outside, with the viewing camera, its frustum and the lights
observer-rendering-the-observer = rendering the observer…
observer-observer = Observer ▾
observer-the-scene-from-outside-drag = The scene from outside: drag to orbit, scroll to zoom.
observer-camera-frame-u-v-n = camera frame u, v, n
observer-clipped-polygons = clipped polygons
observer-frustum-sides = frustum sides
observer-near-plane = near plane
observer-far-plane = far plane
observer-lights = lights

## src/app/views/own_uniforms.rs

own-uniforms-tip = uniform { $kind } { $name } (line { $line }): the range { $lo }..{ $hi } and first value come from the comment after it, `// MIN..MAX = VALUE`; a lesson sets it with "uniforms.{ $name }"
own-uniforms-your-uniforms = Your uniforms

## src/app/views/params/lighting.rs

lighting-i-the-light-s-intensity = I, the light's intensity per RGB channel: L = k·I·…
lighting-intensity-i = intensity I
lighting-f-att-1-a-b = f_att = 1/(a + b·d + c·d²)
lighting-l-position-p-position-p = l = (position − p)/|position − p|
lighting-l-direction-direction-the-light = l = −direction/|direction|: the light travels along it
lighting-direction = direction
lighting-position = position
lighting-the-cone-s-axis = the cone's axis
lighting-axis = axis
lighting-cutoff = cutoff
lighting-f-spot-cos-e-inside = f_spot = (cos φ)^e inside the cutoff angle, 0 outside
lighting-f-spot-cos-e-a = f_spot = (cos φ)^e: a larger e fades the disc towards its rim
lighting-material = material
lighting-ambient-l-a-k-a = ambient: L_a = k_a·c·I_a
lighting-diffuse-l-d-k-d = diffuse: L_d = k_d·c·(I/r²)·max(0, n·l)
lighting-specular-l-s-k-s = specular: L_s = k_s·(I/r²)·max(0, n·h)^p
lighting-shininess-p = shininess p
lighting-p-in-n-h-p = p in (n·h)^p (Blinn-Phong) or (r·v)^p (Phong): larger, a smaller and sharper highlight

## src/app/views/params/mod.rs

params-camera = Camera
params-lookat-eye-at-up-n = LookAt(eye, at, up): n = (eye − at)/|eye − at|, u = up × n/|up × n|, v = n × u
params-eye = eye
params-at = at
params-up = up
params-projection = Projection
params-rasterizer-settings = Rasterizer settings
params-lights = Lights
params-joint-angles = Joint angles
params-objects = Objects
params-m-t-rz-ry-rx = M = T·Rz·Ry·Rx·S
params-translate = translate
params-rotate = rotate °
params-scale = scale
params-q-axis = q₀ axis
params-axis-n = axis n
params-r-n-cos-i-1 = R(n, θ) = cos θ·I + (1 − cos θ)·n·n^T + sin θ·N; q = (cos(θ/2), sin(θ/2)·n)
params-q-axis-2 = q₁ axis
params-slerp-q-q-t-sin = slerp(q₀, q₁, t) = sin((1 − t)Ω)/sin Ω·q₀ + sin(tΩ)/sin Ω·q₁, cos Ω = q₀·q₁: t = 0 is q₀, t = 1 is q₁, at a constant angular speed between
params-angle = angle θ
params-perspective = Perspective
params-frustum = Frustum
params-ortho = Ortho
params-projection-2 = projection
params-vertical-field-of-view-top = Vertical field of view. top = near·tan(fovy/2), right = top·aspect (the review slides' near·tan(fovy) is an erratum).
params-aspect-from-the-viewport = aspect from the viewport
params-the-near-rectangle-l-r = the near rectangle [l, r] × [b, t]
params-near = near{" "}
params-distance-to-the-near-plane = Distance to the near plane z = −near. Small near values waste depth precision: z_ndc = (f+n)/(f−n) − 2fn/((f−n)·d).
params-far = far{" "}
params-distance-to-the-far-plane = Distance to the far plane z = −far.
params-viewport = viewport
params-samples-per-pixel = samples per pixel
params-msaa-coverage-and-depth-per = MSAA: coverage and depth per sample, colour once per pixel and triangle; 4 uses the rotated grid.
params-culling = culling
params-none = none
params-back = back
params-front = front
params-front-faces-are-counter-clockwise = Front faces are counter-clockwise on screen.
params-depth-test = depth test
params-shade-every-sample-ssaa = shade every sample (SSAA)
params-off-multisampling-shades-once-per = Off: multisampling shades once per pixel and triangle at the pixel centre. On: supersampling shades each sample at its own position.
params-perspective-correct-interpolation = perspective-correct interpolation
params-your-shaders-draw-the-picture = Your shaders draw the picture: the shading frequency and the specular term below change nothing on screen; they choose what the shader panel's "pipelens' own" writes.
params-shading = shading
params-unlit = unlit
params-flat = flat
params-flat-once-per-face-gouraud = Flat: once per face. Gouraud: per vertex, colours interpolated. Phong: normals interpolated, lighting per pixel.
params-specular = specular
params-texture-filter = texture filter
params-nearest = nearest
params-bilinear = bilinear
params-nearest-level = nearest level
params-mipmap = mipmap
params-trilinear = trilinear
params-summed-area-table = summed-area table
params-log-max-uw-vh-x = λ = log₂ max(|∂(uw, vh)/∂x|, |∂(uw, vh)/∂y|): the level whose texels are the size of a pixel.
params-anisotropy = anisotropy
params-up-to-n-samples-along = Up to N samples along the footprint's major axis; λ = log₂(major/N).
params-mip-bias = mip bias
params-base-b-y = base θ_b (y)
params-lower-arm-la-z = lower arm θ_la (z)
params-upper-arm-ua-z = upper arm θ_ua (z)
params-torso-y = torso (y)
params-head-y = head (y)
params-left-upper-arm = left upper arm
params-left-lower-arm = left lower arm
params-right-upper-arm = right upper arm
params-right-lower-arm = right lower arm
params-left-upper-leg = left upper leg
params-left-lower-leg = left lower leg
params-right-upper-leg = right upper leg
params-right-lower-leg = right lower leg
params-the-joint-s-rotation-every = The joint's rotation: every part below it in the tree follows (M ← M·local).
params-less-gl-less = < less (GL_LESS)
params-less-or-equal = ≤ less or equal
params-greater = > greater
params-greater-or-equal = ≥ greater or equal
params-always-painter-s-order = always (painter's order)

## src/app/views/pixels/depth_and_mips.rs

depth-and-mips-eye-distance-d-near-far = eye distance d (near → far)
depth-and-mips-window-depth-z-w = window depth z_w
depth-and-mips-curve-legend = z_w(d), near { $near }, far { $far }
depth-and-mips-depths-in-the-image = depths in the image
depth-and-mips-grey-ramp-black-white = grey ramp: black → white
depth-and-mips-mip-pyramid = mip pyramid
depth-and-mips-framed-the-level-read-at = framed: the level read at the inspected pixel, its footprint in cyan

## src/app/views/pixels/draw.rs

draw-overlays-first-20-000-shapes = overlays: first 20 000 shapes only
draw-mip-level = mip level
draw-top-left = {" "}(top/left)

## src/app/views/pixels/hover.rs

hover-after-line = after line { $line }
hover-pixel = pixel
hover-coverage = coverage
hover-depth = depth
hover-eye-distance = eye distance
hover-primitive = primitive
hover-perspective-correct = perspective-correct
hover-affine = affine
hover-the-line-did-not-run = the line did not run here
hover-click-to-inspect = click to inspect
hover-no-object-of-this-scene = No object of this scene is textured: there is no texture lookup to show.
hover-rendering-this-buffer = rendering this buffer…

## src/app/views/pixels/mod.rs

pixels-triangle-edges = Triangle edges
pixels-bounding-boxes = Bounding boxes
pixels-buffer = buffer
pixels-sample-points = Sample points
pixels-zoom-in-to-see-each = Zoom in to see each pixel's sample positions: filled when covered. The patterns are the standard ones: Direct3D's published numbers taken with y up, as Mesa's llvmpipe takes them (OpenGL leaves the positions to the implementation), so this 4× pattern is Direct3D's drawing mirrored vertically.
pixels-mip-pyramid = mip pyramid
pixels-every-level-of-the-texture = Every level of the texture at once: each the 2×2 box filter of the one before.
pixels-variable-picture = variable picture
pixels-the-shader-panel-s-watch = The shader panel's watch over the frame (or its cost view) drawn here, in place of the buffer: a number on a ramp, dark blue the least and yellow the greatest; a condition yellow where it holds; grey checks where no fragment ran the line. Hover for the value at a pixel.
pixels-fit = Fit
pixels-zoom-to-fit-double-click = Zoom to fit (double-click the image)
pixels-linear-eye-distance = linear: eye distance
pixels-z-w-is-not-linear = z_w is not linear in distance: d = 2fn/((f+n) − z_ndc·(f−n)). Most of [0, 1] goes to the near part of the frustum.
pixels-black-at = black at{" "}
pixels-white-at = white at{" "}
pixels-auto-range = auto range
pixels-pixel-view = pixel view

## src/app/views/shader.rs

shader-debugger = Debugger
shader-apply = Apply
shader-compile-and-draw-with-these = Compile and draw with these shaders (Ctrl+Enter)
shader-save = Save
shader-writes-shader-vert-and-shader = Writes shader.vert and shader.frag into the export folder, and inside.glsl or depth_test.glsl when the step runs those functions (in the browser: downloads them). A lesson reads them with shader = {"{"} vertex = "shader.vert", fragment = "shader.frag", inside = "inside.glsl" {"}"}.
shader-saved = Saved:
shader-source = : source
shader-back-to-your-code = ← Back to your code
shader-puts-back-the-code-you = Puts back the code you had before pipelens' own replaced it.
shader-pipelens-own = pipelens' own
shader-start-again-from-pipelens-own = Start again from pipelens' own shading for the current settings, written as GLSL (unlit; flat; Gouraud; Phong shading with n·h or r·v; a bump or normal map): it draws the same pixels. For r·v with flat or Gouraud shading or a bump map, and for a mirror, none is shipped: there, Blinn-Phong per pixel. Your code stays one click away (Back to your code).
shader-the-rasterizer-calls-it-for = The rasterizer calls it for every sample of a triangle's bounding box: p the sample, a, b, c the corners (window pixels, y up, counter-clockwise). It decides coverage in place of pipelens' edge functions E_i(p) ≥ 0 with the top-left rule.
shader-the-rasterizer-calls-it-for-2 = The rasterizer calls it for every sample a triangle covers: z the triangle's window depth there (in [0, 1]), stored what the z-buffer holds (1 where nothing was drawn). true writes z and the triangle into the sample. It replaces the depth comparison of the settings (less: z < stored).
shader-a-b-zier-curve-s = A Bézier curve's drawing calls it for every point of the curve (161 values of t from 0 to 1): p0 … p3 the control points, in the curve's plane. It replaces pipelens' own b(t) = Σ B_i³(t)·P_i.
shader-the-shadow-pass-calls-it = The shadow pass calls it once a frame: light the point light, relative to the plane the shadow falls on, which it takes to be y = 0. Every shadow object is drawn with it in place of pipelens' M_shadow = T(l)·M_p·T(−l); any positive multiple casts the same shadow.
shader-a-b-zier-patch-s = A Bézier patch's drawing calls it for every vertex of its surface grid (25 × 25 values of (u, v) from 0 to 1): p[4i + j] the control point P_ij, row i along v, column j along u. It replaces pipelens' own b(u, v) = Σ Σ B_i³(v)·B_j³(u)·P_ij; the surface keeps pipelens' exact normals.
shader-inside-test = Inside test
shader-depth-test = Depth test
shader-de-casteljau = de Casteljau
shader-shadow-matrix = Shadow matrix
shader-b-zier-patch = Bézier patch
shader-vertex-shader = Vertex shader
shader-fragment-shader = Fragment shader
shader-compiles-but-the-run-stopped = Compiles, but the run stopped; the last good picture stays on screen:
shader-compiled-the-pipeline-calls-these = Compiled: the pipeline calls these functions in place of its own (hover a tab: when, and what it replaces); the shading is pipelens' own.
shader-compiled-the-picture-is-drawn = Compiled: the picture is drawn with these shaders.
shader-the-picture-is-drawn-by = The picture is drawn by pipelens' own shading: Apply (Ctrl+Enter) or edit to draw it with these shaders.
shader-does-not-compile-the-last = Does not compile: the last good picture stays on screen.

## src/app/views/watch_list.rs

watch-list-undeclared-input = it reads `{ $name }`, which your shader does not declare: the frame did not hand it over
watch-list-not-readable = not readable after line { $line }: { $why }
watch-list-no-run-is-kept-here = no run is kept here: inspect a pixel or select a vertex
watch-list-watch-list = Watch list
watch-list-after-line = after line
watch-list-take-it-off-the-list = Take it off the list
watch-list-up-to-this-step-the = up to this step, the run has not run this line
watch-list-add = Add:
watch-list-an-expression-e-g-dot = an expression, e.g. dot(n, l)
watch-list-any-expression-of-this-shader = Any expression of this shader, read just after the step's line in the run shown; Enter adds it.
watch-list-watch = ＋ Watch

## src/app/views/watch_picture.rs

watch-picture-watch-over-the-frame = Watch over the frame:
watch-picture-any-expression-of-your-fragment = Any expression of your fragment shader, read just after the line runs, at every pixel: a number on a ramp (dark blue the least, yellow the greatest), a vector as a colour or one component, a condition where it holds. Grey checks: no fragment ran the line there.
watch-picture-any-expression-of-your-vertex = Any expression of your vertex shader, read just after the line runs at each vertex, and carried to every pixel as a varying is: interpolated over the triangle with perspective-correct weights, (Σ λᵢ·aᵢ/wᵢ)/(Σ λᵢ/wᵢ); an int or a bool flat, from the triangle's last vertex, as GLSL passes them. A number on a ramp (dark blue the least, yellow the greatest), a vector as a colour or one component, a condition where it holds. Grey checks: a corner of the triangle there did not run the line.
watch-picture-e-g-dot-n-l = e.g. dot(n, l) < 0.0
watch-picture-after-line = after line
watch-picture-the-step-s = the step's
watch-picture-watch-after-the-line-of = Watch after the line of the debugger's step.
watch-picture-show = Show
watch-picture-stop = Stop
watch-picture-cost-the-steps-each-fragment = Cost: the steps each fragment ran
watch-picture-at-each-pixel-how-many = At each pixel, how many steps of your fragment shader its fragment ran (the steps the debugger steps through: writes, branches, loop tests and iterations, calls, returns): a loop that runs longer or a branch with more work shows brighter. Dark blue the fewest, yellow the most.
watch-picture-cannot-watch = Cannot watch:
watch-picture-no-triangle-of-this-frame = No triangle of this frame has all three corners through that line.
watch-picture-no-fragment-of-this-frame = No fragment of this frame ran that line.
watch-picture-steps = steps
watch-picture-no-fragment-of-yours-here = no fragment of yours here
watch-picture-a-corner-of-the-triangle = a corner of the triangle here did not run the line
watch-picture-the-line-did-not-run = the line did not run here
watch-picture-pixel = pixel
watch-picture-after-line-2 = after line
watch-picture-as-colour = as colour
watch-picture-true = true
watch-picture-false = false
watch-picture-first-where-it-holds = First where it holds ▶
watch-picture-inspects-the-first-pixel-where = Inspects the first pixel where it holds, reading the picture from the top, and shows its run at the watched line: a breakpoint with a condition, over the whole frame.
watch-picture-x-red-y-green-z = x → red, y → green, z → blue, each clamped to [0, 1]
watch-picture-not-run = not run

## src/app/window.rs

window-parameters = Parameters
window-rendering = Rendering…
window-title-lesson-step = pipelens — { $lesson } — step { $step }/{ $steps }

## src/bench/handouts.rs

handouts-en = en

## src/cli/grade.rs

grade-cannot-be-read = { $file } cannot be read: { $why }
grade-too-large = { $name } holds { $megabytes } MB; a shader is at most { $kilobytes } KB: not graded
grade-not-text = { $name } is not text (it holds bytes that are not UTF-8)
grade-outside-folder = { $name } is a link that leads out of the hand-in's folder: not read
grade-nothing = { $file } holds no shader.vert, shader.frag or function file ({ $functions })
grade-not-work = { $file }: { $why }
grade-other-lesson = { $file } is work on lesson { $lesson }, not on this one
grade-no-work-at = { $file } holds no code for step { $step }
grade-summary = { $handins ->
    [one] 1 hand-in
   *[other] { $handins } hand-ins
}, { $checks ->
    [one] 1 check
   *[other] { $checks } checks
}, { $passed } passed
grade-gradescope-step = Step { $step }: { $title }
grade-gradescope-output = { $passed } of { $total } lab steps passed, each checked pixel by pixel against pipelens' own.
grade-pipelens-failed-while-checking-this = pipelens failed while checking this hand-in (a defect in pipelens, not in the hand-in): please report it
grade-student = student
grade-step = step
grade-passed = passed
grade-matching = matching
grade-feedback = feedback
grade-yes = yes
grade-no = no

## src/export/handout_exercise.rs

handout-exercise-the-shaders-this-step-runs = The shaders this step runs (on yellow: the lines changed from the step before):
handout-exercise-pipelens-own-what-your-code = pipelens' own, what your code must draw

## src/export/mod.rs

export-cannot-create-the-folder = cannot create the folder { $dir }
export-cannot-write = cannot write { $file }

## src/export/lesson.rs

lesson-exercise = Exercise:
lesson-the-debugger-at-pixel = The debugger at pixel
lesson-step-not-drawn = step { $step }: { $why }
lesson-step-watch = step { $step }'s watch

## src/export/picture.rs

picture-watch-title = { $expression } after line { $line }
picture-watch-holds = yellow where it holds, dark blue where not
picture-watch-range = dark blue { $lo } to yellow { $hi }
picture-watch-vector = the vector as a colour
picture-watch-legend-fragment = { $expression } after line { $line }: { $said }; grey checks where no fragment ran the line
picture-watch-legend-vertex = { $expression } after line { $line } of the vertex shader, interpolated over each triangle: { $said }; grey checks where a corner of the triangle did not run the line
picture-mip-level = mip level

## src/observer.rs

observer-eye = eye

## src/spaces.rs

spaces-object-coordinates = object coordinates
spaces-world-coordinates = world coordinates
spaces-eye-coordinates-camera-at-the = eye coordinates: camera at the origin, looking down −z
spaces-clip-coordinates-x-y-z = clip coordinates (x, y, z of the homogeneous point)
spaces-normalized-device-coordinates-the-canonical = normalized device coordinates: the canonical cube [−1, 1]³
spaces-window-coordinates-0-w-0 = window coordinates: [0, W] × [0, H] × [0, 1]

## src/vocabulary/alt_text.rs

alt-text-comma = ,{" "}
alt-text-nothing-drawn = : nothing drawn.
alt-text-list-comma = ,{" "}
alt-text-colon = :{" "}
alt-text-full-stop = {"."}
alt-text-ellipsis = ; …{" "}

## src/vocabulary/buffers.rs

buffers-shown-brighter = { $name } shown ×{ $gain }: { $gain } times brighter than its values
buffers-colour = Colour
buffers-depth = Depth
buffers-coverage = Coverage
buffers-primitive-id = Primitive id
buffers-barycentrics-perspective-correct = Barycentrics (perspective-correct)
buffers-barycentrics-affine = Barycentrics (affine)
buffers-ambient-term = Ambient term
buffers-diffuse-term = Diffuse term
buffers-specular-term = Specular term
buffers-normal = Normal
buffers-texture-coordinates-u-v = Texture coordinates (u, v)
buffers-mip-level = Mip level
buffers-texel-colour = Texel colour
buffers-texture-footprint = Texture footprint
buffers-reflected-environment = Reflected (environment)

## src/vocabulary/comparison.rs

comparison-flat-gouraud-phong = flat | Gouraud | Phong
comparison-affine-perspective-correct = affine | perspective-correct
comparison-1-4-msaa-4-ssaa = 1× | 4× MSAA | 4× SSAA
comparison-nearest-bilinear-trilinear-anisotropic = nearest | bilinear | trilinear | anisotropic
comparison-trilinear-anisotropic-ripmap-summed-area = trilinear | anisotropic | ripmap | summed-area table | EWA
comparison-flat = flat
comparison-affine = affine
comparison-perspective-correct = perspective-correct
comparison-nearest = nearest
comparison-bilinear = bilinear
comparison-trilinear = trilinear
comparison-anisotropic-16 = anisotropic 16×
comparison-summed-area-table = summed-area table

## src/vocabulary/explain.rs

explain-the-triangle-s-vertices-clip = The triangle's vertices: clip → NDC → window
explain-inside-test-edge-functions = Inside test: edge functions
explain-interpolation-at-the-pixel-centre = Interpolation at the pixel centre
explain-texture-lookup = Texture lookup
explain-lighting = Lighting
explain-the-colour = The colour
explain-n-normal-l-to-the = n normal · l to the light · v to the eye


## src/vocabulary/names.rs

names-point-light = point light
names-spotlight = spotlight
names-directional-light = directional light
names-ambient-light = ambient light

## src/vocabulary/profile.rs

profile-position-along-the-yellow-line = position along the yellow line (pixels)
profile-intensity-rec-709-luminance = intensity (Rec. 709 luminance)

## src/vocabulary/stage.rs

stage-model = Model
stage-world = World
stage-view = View
stage-clip = Clip
stage-ndc = NDC
stage-viewport = Viewport
stage-rasterization = Rasterization
stage-depth = Depth
stage-shading = Shading
stage-texturing = Texturing
stage-output = Output
stage-object-coordinates-the-mesh-as = Object coordinates: the mesh as it was modelled, p = (x, y, z, 1).
stage-world-coordinates-m-p-with = World coordinates: M·p, with M = T·Rz·Ry·Rx·S placing each object.
stage-eye-coordinates-v-m-p = Eye coordinates: V·M·p, V = LookAt(eye, at, up); the camera at the origin looking down −z.
stage-clip-coordinates-p-v-m = Clip coordinates: P·V·M·p (homogeneous). Inside the view volume: −w ≤ x, y, z ≤ w.
stage-normalized-device-coordinates-x-y = Normalized device coordinates: (x, y, z)/w, the canonical cube [−1, 1]³.
stage-window-coordinates-x-w-x = Window coordinates: x_w = (x+1)·W/2, y_w = (y+1)·H/2, z_w = (z+1)/2.
stage-which-samples-each-triangle-covers = Which samples each triangle covers: edge functions, the top-left rule, barycentric weights.
stage-the-z-buffer-a-fragment = The z-buffer: a fragment is kept if it is nearer than what the buffer holds.
stage-lighting-i-k-a-i = Lighting: I = k_a·I_a + f_att·(k_d·I_d·max(l·n, 0) + k_s·I_s·max(n·h, 0)^β), evaluated per face, per vertex or per pixel.
stage-texture-lookups-uv-interpolated-log = Texture lookups: uv interpolated, λ = log₂(texels per pixel) picks the mip level; nearest, bilinear, trilinear, anisotropic.
stage-the-final-colour-each-pixel = The final colour: each pixel the mean of its samples.

## src/export/handout.rs

handout-teacher-s-key-every-answer = Teacher's key: every answer printed
handout-before-this-lesson = Before this lesson
handout-dash = {" "}—{" "}
handout-stage = Stage:{" "}
handout-the-animation-as-the-app = The animation, as the app plays it
handout-the-animation-in-frames-from = The animation in frames, from its start to its end:

## src/export/handout_exercise.rs

handout-exercise-your-answer = Your answer (each entry within { $tolerance }):
handout-exercise-question = Question:
handout-exercise-answer = Answer:
handout-exercise-show-the-answer = Show the answer
handout-exercise-the-debugger-at-pixel = The debugger at pixel
handout-exercise-fragment = fragment
handout-exercise-triangle = triangle
handout-exercise-discarded = discarded
handout-exercise-exercise = Exercise:

## src/vocabulary/explain.rs

explain-edge-opposite = the edge opposite corner { $edge }
explain-sample-covered = sample { $index } is covered
explain-sample-not-covered = sample { $index } is not covered
explain-on-a-top-or-left-edge = exactly on edge { $edge }, a top or left edge: counts as inside (top-left rule)
explain-on-a-bottom-or-right-edge = exactly on edge { $edge }, a bottom or right edge: does not count (top-left rule)
explain-nearest-level = the nearest level, at most { $max }
explain-trilinear = trilinear: levels k and k+1 blended by t (λ at most { $max })
explain-four-texels = the four texels read, of level { $level } ({ $width }×{ $height })
explain-directional-light = directional
explain-spot-light = spot
explain-point-light = point
explain-light-towards = light { $index } ({ $kind }): the unit vector towards it
explain-mean-of-samples = the mean of the pixel's { $samples } samples; { $covered ->
        [one] 1 belongs
       *[other] { $covered } belong
    } to this triangle's primitive, the others keep their own colour or the background
explain-behind-the-eye-no-ndc = behind the eye: no NDC; clipping cut the triangle first
explain-the-triangle-crosses-the-view = the triangle crosses the view volume: the pixel lies in a piece of the clipped polygon
explain-the-corners-snapped = the triangle's corners, snapped to 1/256 pixel, counter-clockwise; v_k is vertex k, c_k a corner made by clipping
explain-the-pixel-centre = the pixel centre
explain-depth-is-linear-in-screen = depth is linear in screen space
explain-perspective-correct-interpolation = perspective-correct interpolation
explain-affine-interpolation-for-comparison = affine interpolation, for comparison
explain-derivatives-as-a-gpu-takes = derivatives as a GPU takes them: differences within the pixel's 2×2 quad, at its lower-left pixel (x_q, y_q); the quad's four pixels share them and λ
explain-anisotropic-n-taps-along-the = anisotropic: N taps along the footprint's major axis
explain-0-magnification-level-0 = λ ≤ 0: magnification, level 0
explain-no-mipmap-level-0-always = no mipmap: level 0 always
explain-ripmap-level-i-halves-u = ripmap: level i halves u, level j halves v, each chosen from a side of the footprint's bounding box; a diagonal footprint's box is too big
explain-summed-area-table-the-exact = summed-area table: the exact mean of the texels in the footprint's bounding box, four table reads whatever its size
explain-ewa-the-texels-inside-the = EWA: the texels inside the footprint's ellipse, weighted by a Gaussian, on the level where the ellipse's minor axis is about a texel
explain-nearest-the-texel-containing-the = nearest: the texel containing the point
explain-the-mean-of-the-taps = the mean of the taps
explain-gouraud-lit-at-each-vertex = Gouraud: lit at each vertex, the colours interpolated
explain-flat-lit-once-per-face = flat: lit once per face, at its provoking (last) vertex, with the face normal
explain-textured-the-texel-t-multiplies = textured: the texel T multiplies the ambient and diffuse terms
explain-bump-or-normal-mapping-tilts = bump or normal mapping tilts the normal
explain-a-mirror-it-reflects-its = a mirror: it reflects its environment along r and keeps 1 − k of its own light
explain-the-material-k-a-k = the material: k_a, k_d, k_s and the shininess p
explain-ambient-term = ambient term
explain-distance-attenuation = distance attenuation
explain-the-spotlight-s-cone-half = the spotlight's cone, half-angle θ
explain-diffuse-term-lambert = diffuse term (Lambert)
explain-the-half-vector-between-l = the half vector between l and v
explain-the-mirror-direction-of-l = the mirror direction of l
explain-specular-term-max-0-before = specular term; max(·, 0) before the power, and 0 where n·l ≤ 0
explain-the-sum-of-the-terms = the sum of the terms
explain-the-colour-buffer-keeps-each = the colour buffer keeps each sample's colour clamped to [0, 1]
explain-the-8-bit-colour-in = the 8-bit colour in the image

## src/app/shortcuts.rs

shortcuts-next-step-of-a-lesson = next step of a lesson (next stage without one)
shortcuts-previous-step-previous-stage = previous step (previous stage)
shortcuts-play-or-pause-the-step = play or pause the step's animation (replay the transition)
shortcuts-the-narration-card = the narration card
shortcuts-the-parameters-panel = the parameters panel
shortcuts-the-inspector-matrices-vertices-the = the inspector: matrices, vertices, the pixel explained
shortcuts-the-matrix-card-over-the = the matrix card over the geometry
shortcuts-classroom-mode-large-type-the = classroom mode: large type, the picture first
shortcuts-the-shader-editor-glsl = the shader editor (GLSL)
shortcuts-apply-the-shaders = apply the shaders
shortcuts-the-lesson-editor-record-what = the lesson editor: record what is on screen as steps, word, arrange
shortcuts-the-lesson-editor-saves-its = the lesson editor saves its file, whole or not at all
shortcuts-the-lesson-editor-redoes = the lesson editor redoes
shortcuts-the-lesson-editor-undoes = the lesson editor undoes
shortcuts-shader-debugger-next-step-a = shader debugger: next step (a call run whole)
shortcuts-shader-debugger-one-step-back = shader debugger: one step back
shortcuts-shader-debugger-next-step-into = shader debugger: next step, into a call
shortcuts-shader-debugger-out-of-this = shader debugger: out of this function
shortcuts-shader-debugger-run-to-the = shader debugger: run to the cursor's line
shortcuts-shader-debugger-on-to-the = shader debugger: on to the next breakpoint
shortcuts-shader-debugger-back-to-the = shader debugger: back to the previous breakpoint
shortcuts-shader-debugger-a-breakpoint-on = shader debugger: a breakpoint on the cursor's line (or off); a click on a line number too
shortcuts-full-screen = full screen
shortcuts-text-size = text size
shortcuts-the-keyboard-to-the-picture = the keyboard to the picture, then to the one beside it, then back to the steps (Tab reaches each too)
shortcuts-this-list = this list
shortcuts-wheel-drag = wheel, drag
shortcuts-zoom-at-the-cursor-pan = zoom at the cursor, pan (geometry: orbit)
shortcuts-click = click
shortcuts-select-a-pixel-or-a = select a pixel or a vertex
shortcuts-in-the-picture-the-inspected = in the picture: the inspected pixel moves (Shift: 10 pixels); a geometry view or the observer orbits (Shift: 10×)
shortcuts-in-the-picture-zoom = in the picture: zoom
shortcuts-in-a-geometry-view-the = in a geometry view: the previous or next vertex (Shift: 10 on)
shortcuts-the-keyboard-back-from-the = the keyboard back from the picture or the shader's source (where Tab indents): the arrows step again

## src/app/views/debugger.rs

debugger-watch-not-run-yet = watch `{ $expression }`: up to this step, this fragment has not run line { $line }
debugger-back = ← back
debugger-step-back = step back
debugger-over = → over
debugger-step-over-a-call-run = step over (a call run whole)
debugger-into = ↓ into
debugger-step-into-a-call = step into a call
debugger-out = ↑ out
debugger-step-out-of-this-function = step out of this function
debugger-to-cursor = to cursor
debugger-run-to-the-cursor-s = run to the cursor's line
debugger-breakpoint = ◀ breakpoint
debugger-back-to-the-previous-breakpoint = back to the previous breakpoint
debugger-breakpoint-2 = breakpoint ▶
debugger-on-to-the-next-breakpoint = on to the next breakpoint

## src/spaces.rs

spaces-solid = solid
spaces-dashed = dashed
spaces-dotted = dotted
spaces-dash-dot = dash-dot
spaces-dash-dot-dot = dash-dot-dot
spaces-short-dashes = short dashes
spaces-fate-drawn = drawn
spaces-fate-clipped = clipped
spaces-fate-outside = outside
spaces-fate-culled = culled
spaces-fate-degenerate = degenerate
spaces-fate-not-finite = not finite (NaN or ∞)
# A fate and how its edges are drawn, in a legend written in words: "clipped: dashed".
spaces-fate-and-line = { $fate }: { $line }

## src/vocabulary/alt_text.rs (with variables)

alt-text-buffer = { $name } buffer
alt-text-size = , { $w }×{ $h } pixels
alt-text-beside = {" "}(beside: { $others })
alt-text-at-pixel = {" "}At pixel ({ $x }, { $y }), { $object }'s triangle { $triangle }
alt-text-stage = { $stage } stage
watch-picture-after-vertex-line = after line { $line } of the vertex shader, interpolated
depth-and-mips-curve-alt = depth curve: window depth z_w against eye distance d from near { $near } to far { $far }

## src/lab/words.rs: a lab's verdict

lab-words-passed = Passed: all { $total } pixels match pipelens' own (each channel within { $tolerance }/255).
lab-words-colours-differ = colours by up to { $largest }/255
lab-words-covered-differently =
    { $n ->
        [one] 1 is covered differently
       *[other] { $n } are covered differently
    }
lab-words-at-another-depth =
    { $n ->
        [one] 1 lies at another depth
       *[other] { $n } lie at another depth
    }
lab-words-another-triangle =
    { $n ->
        [one] 1 belongs to another triangle
       *[other] { $n } belong to another triangle
    }
# Between the clauses of what differs, and between a matrix's differing entries.
lab-words-clause-separator = {"; "}
lab-words-not-yet =
    Not yet: { $matching } of { $total } pixels match; { $differ ->
        [one] 1 differs
       *[other] { $differ } differ
    } ({ $how }). The first, reading from the top, is { $first }.
lab-words-at-the-pixel = At the inspected pixel { $pixel } your `{ $name }` (line { $line }) is { $yours }; pipelens' own shader has { $theirs }.
lab-words-at-the-vertex = At vertex { $row } (a corner of the first wrong pixel's triangle) your vertex shader's `{ $name }` (line { $line }) is { $yours }; pipelens' own has { $theirs }.
lab-words-not-normalized = {" "}Yours has length { $length }, pipelens' 1: is it normalized?
lab-words-first-vertex = The first vertex off is row { $row }: your clip position { $yours }, pipelens' { $theirs }.
lab-words-matrix-entry = row { $row }, column { $column } is { $yours } ({ $matrix } has { $theirs })
lab-words-matrix-more = ; and { $more } more
lab-words-matrix =
    Your `{ $name }` (line { $line }) is pipelens' { $matrix } but for { $n ->
        [one] one entry
       *[other] { $n } entries
    }: { $entries }{ $more }.
lab-words-curve = curve
lab-words-surface = surface
lab-words-curve-passed = Passed: all { $total } points of your { $what } lie within { $tolerance } of pipelens' { $b }.
lab-words-curve-first = {" "}The first, { $at }: yours { $yours }, pipelens' { $theirs }.
lab-words-curve-not-yet = Not yet: { $matching } of { $total } { $what } points lie within { $tolerance } of pipelens' { $b } (the farthest is { $largest } away).{ $first }

## src/vocabulary/names.rs: the built-in names of figures' parts and usual objects (looked up as part-NAME)

part-robot-arm = robot arm
part-humanoid = humanoid
part-base = base
part-lower-arm = lower arm
part-upper-arm = upper arm
part-torso = torso
part-head = head
part-left-arm-upper = left arm upper
part-left-arm-lower = left arm lower
part-right-arm-upper = right arm upper
part-right-arm-lower = right arm lower
part-left-leg-upper = left leg upper
part-left-leg-lower = left leg lower
part-right-leg-upper = right leg upper
part-right-leg-lower = right leg lower
part-floor = floor
part-cube = cube
part-sphere = sphere
part-wall = wall
part-triangle = triangle
part-two-triangles = two triangles
part-torus = torus
part-quad = quad
part-curve = curve
part-mirror = mirror
part-body = body
part-arm = arm
part-lower = lower
part-upper = upper
part-left-upper-arm = left upper arm
part-left-lower-arm = left lower arm
part-right-upper-arm = right upper arm
part-right-lower-arm = right lower arm
part-left-upper-leg = left upper leg
part-left-lower-leg = left lower leg
part-right-upper-leg = right upper leg
part-right-lower-leg = right lower leg
names-shadow-of = shadow of { $object }

## src/lesson/param/describe.rs: a parameter's words (looked up as param-KEY), as the panel says them

param-camera = camera
param-projection = projection
param-render = render
param-lights = lights
param-shadow = shadow
param-eye = eye
param-at = at
param-up = up
param-near = near
param-far = far
param-translate = translate
param-rotate = rotate
param-scale = scale
param-color = color
param-axis = axis
param-axis-angle = axis angle
param-slerp-axis = slerp axis
param-slerp-angle = slerp angle
param-slerp-t = slerp t
param-position = position
param-direction = direction
param-intensity = intensity
param-cutoff = cutoff
param-exponent = exponent
param-light = light
param-shininess = shininess p
param-normals = normals
param-lod-bias = lod bias
param-max-steps = max steps
param-samples = samples
param-anisotropy = anisotropy
param-uniforms = uniforms
# "B of A": a part of a whole (an object's field); -latin where the part is a Latin word ("fovy").
describe-of = { $part } of { $whole }
describe-of-latin = { $part } of { $whole }
describe-light-part = { $light } { $part }
describe-group-part = { $group } { $part }
describe-group-part-latin = { $group } { $part }

## src/lab/quantity.rs

quantity-uv-differs = At the inspected pixel { $pixel } your `{ $name }` (line { $line }) is { $yours }; pipelens' uv there, interpolated perspective-correctly, is { $theirs }.
quantity-lod-differs = At the inspected pixel { $pixel } your `{ $name }` (line { $line }) gives λ = { $yours }; pipelens' λ there is { $theirs }: the footprint is L = 2^λ = { $footprint } texels a pixel step (uv { $uv }).
quantity-texel-differs = At the inspected pixel { $pixel } your `{ $name }` (line { $line }) gives { $yours }; pipelens' filter reads { $theirs } there (uv { $uv }).
quantity-the-texture = the { $w } × { $h } texture
quantity-the-level = level { $k } ({ $w } × { $h })
quantity-bilinear-differs = At the inspected pixel { $pixel } your `{ $name }` (line { $line }) gives { $yours }; pipelens' bilinear filter reads { $theirs } there: uv { $uv } on { $on } is (x, y) = ({ $x }, { $y }) (x = u·w − ½, y = v·h − ½), between texels ({ $i }, { $j }) and ({ $i1 }, { $j1 }), mixed by s = { $s } and t = { $t }.

## src/lesson/answer.rs

answer-tolerance-and-relative = ±{ $t }; an entry under { $below } within 5 % of itself
answer-your-value = your value
answer-named-entry = { $name }
answer-component = component { $n }
answer-row-column = row { $row }, column { $column }
answer-list-separator = { "; " }
answer-right = Right: every entry within { $tolerance } of the answer.
answer-still-empty = Still empty: { $cells }.
answer-not-a-number = { $cell }: "{ $text }" is not a number ({ $why }).
answer-too-large = { $cell } = { $typed } is { $by } too large
answer-too-small = { $cell } = { $typed } is { $by } too small
answer-not-yet = Not yet ({ $off } of { $entries } off, tolerance { $tolerance }): { $each }.

## src/lab/submission.rs

submission-not-a-lab = step { $step } of { $lesson } is not a lab
submission-file-does-not-compile = Does not compile: { $file }.glsl, { $first }
submission-its-run-stopped = It compiles, but its run stopped: { $why }
submission-does-not-compile = Does not compile: { $first }{ $more ->
        [0] {""}
        [one] { " " }(and 1 more message)
       *[other] { " " }(and { $more } more messages)
    }

## src/vocabulary/compile.rs

compile-cannot-stand-here = `{ $found }` cannot stand here
compile-file-ends-where = the file ends where { $expected } should follow
compile-should-come-first = `{ $found }` cannot stand here: { $expected } should come first
compile-or = { " or " }
compile-token-a-name = a name
compile-token-a-type = a type
compile-token-a-whole-number = a whole number
compile-token-a-number = a number
compile-token-true-or-false = true or false
compile-token-the-end-of-the-file = the end of the file
compile-missing-semicolon = a `;` is missing at the end of this line
compile-unexpected-end = the file ends too early: a `{ "}" }` or `)` is missing
compile-unknown-variable = `{ $n }` is not declared here: declare it before its first use, or check its spelling
compile-unknown-type = `{ $n }` is not a GLSL type (float, vec2, vec3, vec4, int, bool, mat3, mat4, …)
compile-no-such-field = this value has no such field or component
compile-no-field-named = this value has no field or component `{ $n }` (a vec3 has x, y, z; a vec2 has no z)
compile-no-function-matches = no function matches this call: check its name and the types of its arguments
compile-no-function-named = no function `{ $n }` takes these arguments: check its name, the number and types of its arguments, and that it is declared above this line
compile-already-declared = `{ $n }` is declared twice here: give the second one another name, or assign to the first without its type
compile-function-already-defined = this function is defined twice
compile-cannot-combine = the two sides of this operator have types it cannot combine: a vec3 with a vec4 needs v.xyz or vec4(v, 1.0); an int with a float needs float(i) or 1.0 for 1
compile-too-many-arguments = this constructor is given more numbers than its type holds (vec3 takes 3, mat4 takes 16)
compile-bad-constructor = this type cannot be built from these arguments
compile-not-constant = this must be known when the shader is compiled: a number, or a `const` made of numbers
compile-not-assignable = this cannot be assigned to: a `uniform`, an `in` input and a `const` are read-only — copy it into a local variable first
compile-void-value = a `void` function returns nothing, so its call has no value to use here
compile-version-not-first = `#version` must be the first line of the shader
compile-invalid-version = GLSL has no version `{ $v }`: write `#version 330 core` (or 110, 120 for the old GLSL)
compile-float-modulo = GLSL's `%` takes whole numbers only (int, uint, ivec…): for floats write mod(a, b)
compile-bad-swizzle = this swizzle is not allowed: on the left of `=` each component once (v.xy, not v.xx), and at most four
compile-type-mismatch = the value's type is not the variable's type: a vec3 into a vec4 needs building, vec4(v, 1.0); a vec4 into a vec3 needs picking, v.xyz; a float from an int needs float(i)
compile-return-type = what this function returns is not its declared type, or it can end without `return`
compile-integer-overflow = this whole number is too large for 32 bits
compile-not-implemented = pipelens does not run this form of GLSL yet ({ $what })
compile-not-run-yet = pipelens does not run `{ $name }` yet
compile-sampler-parameter = pipelens passes only a `sampler2D` or a `samplerCube` to a function: it binds no `{ $ty }`
compile-recursion = GLSL does not allow recursion: `{ $name }` calls itself
compile-defined-below = `{ $name }` is called before it is defined: move its definition above, or declare it above (its first line ending in `;`)
compile-argument-types = the arguments do not match the parameters of `{ $name }` { $parameters }: check each argument's type
compile-at = line { $line }, column { $column }: { $said }
compile-vertex-shader = vertex shader
compile-fragment-shader = fragment shader
compile-stage-message = { $stage }, { $message }
compile-file-message = { $file }.glsl, { $message }
compile-endless-loop = the loop ran more than { $budget } steps (an endless loop? If it is meant to run longer, raise the limit with `max_steps` under [scene.render])
compile-index-out-of-range-of = index { $index } is out of range: `{ $name }` has { $count } elements (0 to { $last })
compile-index-out-of-range = index { $index } is out of range (0 to { $last })
compile-texel-outside = texelFetch at ({ $i }, { $j }) level { $level } is outside the texture
compile-division-by-zero = integer division by zero
compile-remainder-by-zero = integer remainder (%) by zero
compile-did-you-mean = ; did you mean `{ $name }`?
compile-unknown-uniform = pipelens sets no uniform called `{ $name }`; the uniforms it sets: { $uniforms }. A uniform of your own is a float, int, bool, vec2, vec3 or vec4, its control in a comment after it: `// 0..4 = 1.5`{ $meant }
compile-own-uniform-control = `{ $name }` is a uniform of your own; its comment reads like its control (`// MIN..MAX = VALUE`) but { $why }
compile-uniform-type = pipelens' `{ $name }` is a { $expected } ({ $meaning }), declared here as { $written }
compile-texture-type = pipelens binds `{ $name }` as a { $expected }, declared here as { $written }
compile-unknown-texture = pipelens binds no texture called `{ $name }`; the object's texture is `uniform sampler2D tex;`, its bump or normal map `uniform sampler2D detail;`, the cube map it mirrors `uniform samplerCube environment;`{ $meant }
compile-unknown-attribute = pipelens feeds no vertex attribute called `{ $name }`; the attributes: { $attributes }{ $meant }
compile-one-colour-output = pipelens draws into one colour buffer: declare one `out vec4` for the fragment's colour
compile-uniform-written = `{ $name }` is a uniform: a shader reads it, it cannot assign to it
compile-no-position = the vertex shader never writes `gl_Position` (the clip-space position): add `gl_Position = mvp * vec4(position, 1.0);`
compile-no-output = the fragment shader has no output: declare `out vec4 color;` and write the fragment's colour into it
compile-output-not-written = the fragment shader never writes `{ $name }`: the fragment would have no colour
compile-varying-components = `{ $name }` has { $here } components here but { $vertex } in the vertex shader: declare it with the same type in both
compile-no-varying-source = the vertex shader has no output `{ $name }` to interpolate into this input; its outputs: { $outputs }
compile-no-outputs = none
compile-hook-signature = { $calls }: define it with exactly that signature (no `main`, no inputs or outputs of your own)
compile-hook-calls-inside = the rasterizer calls `{ $signature }` for every sample
compile-hook-calls-depth-test = the rasterizer calls `{ $signature }` for every sample a triangle covers
compile-hook-calls-curve = a Bézier curve's drawing calls `{ $signature }` for every point of the curve
compile-hook-calls-shadow-matrix = the shadow pass calls `{ $signature }` once a frame, for the plane y = 0
compile-hook-calls-patch = a Bézier patch's drawing calls `{ $signature }` for every vertex of the surface grid

## src/vocabulary/run.rs

run-cannot-draw = the scene cannot be drawn: { $why }
run-problem-separator = {"; "}
run-shadow-matrix = shadow_matrix(vec3({ $x }, { $y }, { $z })) returned a matrix that is not finite (a division by zero?): { $matrix }
run-code = { $part } of { $object }, { $message }
run-code-in-file = { $part } of { $object }, { $file }, { $message }
run-part-inside = inside test
run-part-depth-test = depth test
run-part-curve = de_casteljau()
run-part-shadow-matrix = shadow_matrix()
run-part-patch = bezier_patch()
run-camera-not-finite = the camera's eye, at and up must be finite
run-eye-at-coincide = the eye and the point looked at coincide ({ $at }): there is no view direction
run-up-parallel = the up vector { $up } is parallel to the view direction { $dir }: u = v_up × n is zero, so the camera frame is undefined (choose another up vector)
run-zero-axis = the rotation axis is the zero vector
run-object-transform = object `{ $name }`: its transform must be finite
run-object-colour = object `{ $name }`: its colour must be finite
run-viewport-width = the viewport width must be between 1 and { $max } pixels, got { $got }
run-viewport-height = the viewport height must be between 1 and { $max } pixels, got { $got }
run-capture-too-large = { $width }×{ $height } pixels × { $samples } samples needs about { $megabytes } MB for a capture, more than the { $allowed } MB allowed; lower the size or the sample count
run-background = the background colour must be finite
run-fovy = fovy must be between 0° and 180° (exclusive), got { $fovy }
run-aspect = aspect must be a positive number, got { $aspect }
run-left-right = left must be less than right, got left = { $left }, right = { $right }
run-bottom-top = bottom must be less than top, got bottom = { $bottom }, top = { $top }
run-near = near must be positive for a perspective projection (it is a distance in front of the eye), got { $near }
run-far-near = far must be greater than near, got near = { $near }, far = { $far }
run-projection-not-finite = every projection parameter must be a finite number

## src/lab/samples.rs

samples-inside = inside
samples-outside = outside
samples-writes-the-fragment = writes the fragment
samples-keeps-what-is-stored = keeps what is stored
samples-on-a-top-or-left-edge = { " " }(on it: a top or left edge)
samples-on-neither-top-nor-left = { " " }(on it: neither a top nor a left edge)
samples-edge-value = E{ $edge } = { $value }{ $on }
samples-inside-differs = At pixel ({ $x }, { $y }), the sample ({ $sx }, { $sy }) against triangle { $triangle }: { $edges }. pipelens: { $theirs }; your inside(): { $yours }.
samples-depth-differs = At pixel ({ $x }, { $y }), sample { $sample }: triangle { $triangle }'s fragment has z = { $z } and the z-buffer holds { $stored }. pipelens { $theirs }; your depth_test(z, stored) { $yours }.

## src/lesson/forbid.rs

forbid-own-uniform = Not yet: { $file } line { $line } declares pipelens' own `{ $name }` — this lab asks you to compute it yourself, so the uniform is not yours to use here.
forbid-own-function = Not yet: { $file } line { $line } calls `{ $name }()` — this lab asks you to compute what it returns yourself, so it is not yours to call here.

## src/lesson/typed.rs

typed-unexpected = unexpected `{ $what }`
typed-unclosed = a `(` is not closed
typed-missing-at-end = a number is missing at the end
typed-not-a-number = `{ $what }` is not a number
typed-unknown-name = `{ $what }` is not a function pipelens knows: sqrt, sin, cos, tan, cot, asin, acos, atan, ln, log2, log10, exp, deg, pi
typed-not-finite = not a finite number
typed-several = several numbers in one box: type one number in each box

## src/vocabulary/formulas.rs

formula-frustum-l-r-b-t-near = Frustum(l, r, b, t, near, far): shear, scale, then perspective normalization
formula-frustum-right-right-top-top-near = Frustum(−right, right, −top, top, near, far) with top = near·tan(fovy/2), right = top·aspect
formula-m-t-r-n-rz-ry = M = T·R(n, θ)·Rz·Ry·Rx·S: scale, rotate about x, y, z, then about the axis n, then translate
formula-m-t-r-slerp-q-q = M = T·R(slerp(q₀, q₁, t))·Rz·Ry·Rx·S: scale, rotate about x, y, z, then part way between two orientations, then translate
formula-the-rotation-part-way-from-the = the rotation part way from the first orientation to the second, along the shorter arc
formula-m-t-rz-ry-rx-s = M = T·Rz·Ry·Rx·S: scale, rotate about x, y, z, then translate
formula-m-parent-t-rz-ry-rx = M = parent·T·Rz·Ry·Rx·S: the object's own transform, then its parent's
formula-m-m-local-the-parent-s = M ← M·local: the parent's composite times this part's placement
formula-t-0-h-0-t-l = T(0, h+ε, 0)·[T(l)·M_p·T(−l)]·T(0, −h, 0): project from the light onto y = h
formula-t-joint-on-the-torso-rx = T(joint on the torso)·Rx(θ)
formula-l-r-b-t-f-n = [l,r]×[b,t]×[f,n] → [−1,1]³: translate the centre to the origin, then scale
formula-back-up-to-the-plane-lifted = back up to the plane, lifted by ε
formula-your-shadow-matrix-l = your shadow_matrix(l)
formula-centre-the-view-volume-at-the = centre the view volume at the origin, then scale it to the cube [−1,1]³
formula-move-the-light-back-to-xl = move the light back to (xl, yl, zl)
formula-move-the-light-to-the-origin = move the light to the origin
formula-perspective-normalization-far-near-far-near = perspective normalization: α = −(far+near)/(far−near), β = −2·far·near/(far−near)
formula-perspective-projection-onto-y-yl = perspective projection onto y = −yl
formula-project-from-the-light-onto-the = project from the light onto the plane y = 0
formula-rotation-about-an-arbitrary-axis-by = rotation about an arbitrary axis, by aligning it with z
formula-rows-u-v-n-and-p = rows u, v, n and −p·u, −p·v, −p·n with n = (eye−at)/|eye−at|, u = v_up×n/|v_up×n|, v = n×u; equals GAMES101's R_view·T_view with g = at − eye, t = up
formula-rows-g-t-t-g = rows: g×t, t, −g
formula-shear-h-cot-l-r-2 = shear H(θ, φ): cot θ = (l+r)/(2·near), cot φ = (t+b)/(2·near)
formula-squish-the-frustum-into-a-box = squish the frustum into a box (n and f fixed), then the orthographic projection
formula-the-joint = the joint
formula-the-part-s-composite-times-its = the part's composite times its instance matrix
formula-the-plane-to-y-0 = the plane to y = 0
formula-the-rotation-itself-about-z = the rotation itself, about z
formula-to-the-joint = to the joint
formula-undo-the-turn-into-the-xz = undo the turn into the xz plane
formula-undo-the-turn-onto-z = undo the turn onto z
formula-where-the-figure-stands = where the figure stands
formula-x-n-x-z-y-n = x' = n·x/z, y' = n·y/z; z of the near and far planes kept
formula-x-w-x-1-width-2 = x_w = (x+1)·width/2, y_w = (y+1)·height/2, z_w = (z+1)/2

## src/vocabulary/glsl.rs

glsl-pipelens-per-pixel-phong-frequency-lighting = pipelens' per-pixel (Phong-frequency) lighting with the Blinn-Phong model, as a shader:
glsl-l-k-a-c-i-a = L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(n·h, 0)^p)
glsl-with-h-normalize-l-v-f = with h = normalize(l + v), f_att = 1/(a + b·d + c·d²), f_spot = (cos φ)^e inside the cone.
glsl-pipelens-declares-these-before-your-code = pipelens declares these before your code (a program of your own declares them itself):
glsl-the-surface-colour = the surface colour
glsl-pipelens-flat-shading-the-fragment-half = pipelens' flat shading, the fragment half: one normal per face and one lighting per face.
glsl-the-face-normal-is-the-cross = The face normal is the cross product of two directions in the face's plane: as x and y move
glsl-on-the-screen-the-world-position = on the screen the world position p moves within the face, so ∂p/∂x and ∂p/∂y are two such
glsl-directions-and-n-face-normalize-dfdx = directions and n_face = ±normalize(dFdx(p) × dFdy(p)), + for a front face. (Only the
glsl-direction-holds-in-general-p1-p0 = direction holds in general: (p1 − p0)×(p2 − p0) = 2·area·(∂p/∂x × ∂p/∂y) holds for an affine
glsl-mapping-alone-not-under-perspective = mapping alone, not under perspective.)
glsl-the-blinn-phong-lighting-is-that = The Blinn-Phong lighting is that of gouraud.vert, at the provoking vertex f_pos: every
glsl-fragment-of-the-face-computes-the = fragment of the face computes the same colour. A textured surface is lit white (c = 1) and
glsl-its-texel-modulates-ambient-and-diffuse = its texel modulates ambient and diffuse, as with Gouraud shading.
glsl-pipelens-flat-shading-the-vertex-half = pipelens' flat shading, the vertex half: the vertex stage of pipelens.vert, and the values a
glsl-face-is-lit-with-opengl-gives = face is lit with. OpenGL gives a `flat` output the provoking (last) vertex's value across the
glsl-whole-triangle-the-face-is-lit = whole triangle: the face is lit at that vertex, with its colour.
glsl-displacement-mapping-s-height-map-none = displacement mapping's height map (none: black)
glsl-its-k-0-without-one = its k (0 without one)
glsl-world-position-interpolated-its-derivatives-give = world position, interpolated: its derivatives give the face normal
glsl-the-provoking-vertex-s-world-position = the provoking vertex's world position
glsl-and-its-colour = and its colour
glsl-displacement-mapping-moves-the-vertex-along = Displacement mapping moves the vertex along its normal: p' = p + k·h(u, v)·n, h the
glsl-height-map-s-luminance-bilinear-level = height map's luminance (bilinear, level 0).
glsl-pipelens-gouraud-shading-the-fragment-half = pipelens' Gouraud shading, the fragment half: the lighting of the three vertices arrives
glsl-interpolated-a-texel-modulates-the-ambient = interpolated; a texel modulates the ambient and diffuse part (OpenGL's GL_MODULATE), the
glsl-specular-part-is-added-on-top = specular part is added on top.
glsl-ambient-diffuse-lit-with-a-white = ambient + diffuse, lit with a white surface when textured
glsl-pipelens-gouraud-shading-the-vertex-half = pipelens' Gouraud shading, the vertex half: the Blinn-Phong lighting of each vertex, once per
glsl-vertex-with-its-own-normal = vertex, with its own normal,
glsl-l-k-a-c-i-a-2 = L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(n·h, 0)^p),
glsl-sent-to-the-fragment-stage-to = sent to the fragment stage to be interpolated across the triangle (gouraud.frag). A textured
glsl-surface-is-lit-white-here-c = surface is lit white here (c = 1); its texel modulates ambient and diffuse per pixel.
glsl-ambient-diffuse = ambient + diffuse
glsl-specular = specular
glsl-pipelens-per-pixel-blinn-phong-lighting = pipelens' per-pixel Blinn-Phong lighting (blinn_phong.frag) with a bump or normal map: the
glsl-interpolated-normal-n-is-tilted-in = interpolated normal n is tilted in the tangent frame before lighting.
glsl-tangent-frame-t-p-u-b = Tangent frame: T = ∂p/∂u, B = ∂p/∂v. The screen derivatives of p and uv obey
glsl-dfdx-p-t-dfdx-u-b = dFdx(p) = T·dFdx(u) + B·dFdx(v),  dFdy(p) = T·dFdy(u) + B·dFdy(v),
glsl-two-equations-solved-for-t-and = two equations solved for T and B (the same T, B as from the triangle's edges).
glsl-t-normalize-t-n-n-t = T' = normalize(T − n(n·T)), B' = ±n×T' (the sign of B), n' = normalize(T'·x + B'·y + n·z):
glsl-bump-map-games101-x-y-z = bump map (GAMES101): (x, y, z) = (−dU, −dV, 1), dU = k_h·k_n·(h(u + 1/w, v) − h(u, v)),
glsl-dv-k-h-k-n-h = dV = k_h·k_n·(h(u, v + 1/h) − h(u, v)), h the texel's luminance;
glsl-normal-map-x-y-z-2 = normal map:          (x, y, z) = 2·texel − 1.
glsl-0-none-1-bump-map-2 = 0 none, 1 bump map, 2 normal map
glsl-k-h-k-n = k_h·k_n
glsl-pipelens-per-pixel-blinn-phong-lighting-2 = pipelens' per-pixel Blinn-Phong lighting of a mirror (environment mapping), as a shader:
glsl-l-1-k-ambient-diffuse-specular = L = (1 − k)·(ambient + diffuse) + specular + k·env(r),   r = 2(n·v)n − v = reflect(−v, n)
glsl-with-ambient-k-a-c-i = with ambient = Σ k_a·c·I_a, diffuse = Σ f_att·f_spot·k_d·c·I·max(n·l, 0),
glsl-specular-f-att-f-spot-k = specular = Σ f_att·f_spot·k_s·I·max(n·h, 0)^p, env(r) the cube map seen in direction r and
glsl-k-the-reflectivity-a-mirror-shows = k the reflectivity: a mirror shows k of what it reflects and keeps 1 − k of its own light.
glsl-the-surroundings-x-x-y-y = the surroundings: +x, −x, +y, −y, +z, −z
glsl-k = k
glsl-the-mirror-direction-2-n-v = the mirror direction 2(n·v)n − v
glsl-env-r = env(r)
glsl-the-height-or-normal-map-bilinear = the height or normal map: bilinear, repeating, level 0
glsl-the-luminance-of-the-height-map = The luminance of the height map at uv: h(u, v).
glsl-n-tilted-by-the-bump-or = n tilted by the bump or normal map at uv.
glsl-the-uvs-do-not-grow-across = the uvs do not grow across this triangle: no frame
glsl-pipelens-per-pixel-phong-frequency-lighting-2 = pipelens' per-pixel (Phong-frequency) lighting with Phong's reflection model, as a shader:
glsl-l-k-a-c-i-a-3 = L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(r·v, 0)^p)
glsl-with-r-reflect-l-n-2 = with r = reflect(−l, n) = 2(n·l)n − l, f_att = 1/(a + b·d + c·d²), f_spot = (cos φ)^e inside
glsl-the-cone-blinn-phong-frag-differs = the cone. blinn_phong.frag differs in one line: n·h in place of r·v.
glsl-pipelens-own-vertex-stage-as-a = pipelens' own vertex stage as a shader: the position (displaced, with a displacement map)
glsl-through-m-v-and-p-one = through M, V and P one matrix at a time (model → world → eye → clip, in the order the vertex
glsl-table-shows-them-and-what-the = table shows them), and what the fragment stage interpolates (world position, unit world normal, texture coordinates, colour).
glsl-world-position-m-p = world position M·p
glsl-world-normal-m-t-n-normalized = world normal (M⁻¹)^T·n, normalized (interpolation shortens it again)
glsl-pipelens-unlit-shading-as-a-shader = pipelens' unlit shading as a shader: the surface colour as it is, the texel where the object
glsl-is-textured-else-the-vertex-colour = is textured, else the vertex colour (interpolated).

## src/vocabulary/trace.rs

trace-if-true = if: true → then
trace-if-false = if: false → else
trace-iteration = loop: iteration { $k }
trace-loop-holds = loop condition: true → another iteration
trace-loop-ends = loop condition: false → the loop ends
trace-break = break: the loop ends
trace-continue = continue: on to the next iteration
trace-call = call { $name }()
trace-returns = { $name }() returns { $value }
trace-return-from = return from { $name }()
trace-discard = discard: the fragment is thrown away

## src/app/views/shader_source.rs

shader-source-gutter = Line numbers 1 to { $lines } (click one to set or clear a breakpoint)
shader-source-gutter-breakpoints = ; breakpoints at { $lines }
shader-source-gutter-current = ; the debugger is at line { $line }
shader-source-gutter-messages = ; a message at { $lines }
