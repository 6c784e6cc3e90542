# pipelens: 界面的简体中文。
# The interface in Chinese (simplified characters); a message missing here is shown in English.

language-name = 中文

## src/app/chrome.rs

chrome-help-keyboard-shortcuts = 帮助：键盘快捷键
chrome-keyboard-shortcuts-f1 = 键盘快捷键（F1）
chrome-switch-the-language = 切换语言
chrome-classroom = 课堂模式
chrome-large-type-and-high-contrast = 投影用的大字号与高对比度，画面优先（C）。F11：全屏，Ctrl +/−：字号，←/→：步骤或阶段，空格：播放。
chrome-the-file-changed-on-disk = 文件在磁盘上被修改后无法加载；继续运行上一个正确的版本：
chrome-close-this-message = 关闭此消息
chrome-close-the-keyboard-shortcuts = 关闭键盘快捷键（F1）
chrome-previous-step = 上一步
chrome-previous-step-or-page-up = 上一步（← 或 Page Up）
chrome-step = 步骤
chrome-next-step = 下一步
chrome-next-step-or-page-down = 下一步（→ 或 Page Down）
chrome-pause = ‖ 暂停
chrome-play = ▶ 播放
chrome-play-or-pause-the-animation = 播放或暂停动画（空格）
chrome-narration = 讲解
chrome-show-or-fold-the-narration = 显示或收起画面上的讲解（N）
chrome-parameters = 参数
chrome-the-camera-projection-rasterizer-and = 相机、投影、光栅化与物体（P）
chrome-inspector = 检查器
chrome-matrices-the-vertex-table-the = 矩阵、顶点表、像素检查器（I）
chrome-matrix = 矩阵卡片
chrome-the-stage-s-matrix-over = 在几何视图上显示本阶段的矩阵（M）
chrome-shader = 着色器
chrome-write-the-vertex-and-fragment = 用 GLSL 编写顶点与片元着色器；Ctrl+Enter 应用（S）
chrome-show = 显示 ▾
chrome-download-handout = 下载讲义
chrome-the-lesson-s-handout-in = 以当前语言下载本课讲义：一个 HTML 文件，图片都在其中，可打印（渲染每一步需要几秒）。各缓冲的快照：请用桌面版或 `pipelens export`。
chrome-download-my-work = 下载我的作业
chrome-one-file-with-this-lesson = 一个文件，包含你在本课每一步最后运行的代码和填写的答案（LESSON-work.toml）：交上这个文件；老师用 `pipelens grade 课程 文件` 评分。
chrome-export = 导出 ▾
chrome-folder = 文件夹
chrome-the-folder-the-snapshot-is = 快照写入的文件夹（不存在时创建）。
chrome-export-snapshot = 导出快照
chrome-every-buffer-as-png-and = 每个缓冲的 PNG 与 capture.json，与 `pipelens export` 相同。
chrome-export-handout-and-slides = 导出讲义与幻灯片
chrome-the-lesson-s-handout-in-2 = 用当前语言导出本课的讲义（index.html，图片都在其中，可打印）和每步一张 1920×1080 的幻灯片（slides/），与 `pipelens export 课程 --slides` 相同。
chrome-export-my-work = 导出我的作业
chrome-one-file-with-this-lesson-2 = 一个文件，包含你在本课每一步最后运行的代码和填写的答案（LESSON-work.toml，写入上面的文件夹）：交上这个文件；老师用 `pipelens grade 课程 文件` 评分。
chrome-cancel-export = 取消导出
chrome-stops-between-two-files-those = 在两个文件之间停止：已写入的文件保持完整。
chrome-error = 错误：{ $message }
chrome-showing-the-last-good-frame = （显示上一个正确的帧）
chrome-triangles = 个三角形
chrome-frame = 帧
chrome-vertex = 顶点
chrome-clip = 裁剪
chrome-raster = 光栅化
chrome-resolve = 解析
chrome-keyboard-shortcuts = 键盘快捷键
chrome-triangles-dropped-gl-position-nan = 个三角形被丢弃：gl_Position 为 NaN 或 ∞
chrome-a-vertex-shader-wrote-a = 顶点着色器写出的 gl_Position 不是有限数（除以零、normalize(vec3(0.0))）：无法据此绘制，所以它的三角形在裁剪之前就被丢弃。顶点表标签页显示该顶点的运行过程。
chrome-fragments-shaded = 个片元已着色
chrome-discarded = 个被丢弃
chrome-the-fragment-shader-ran-once = 片元着色器对每个片元运行一次（2×2 像素块的辅助通道不计）；这些被 `discard` 丢弃。
chrome-pixels-nan-or-drawn-black = 个像素为 NaN 或 ∞（画成黑色）
chrome-a-shader-s-colour-was = 着色器输出的颜色不是有限数，例如 normalize(vec3(0.0)) 或 0.0/0.0：单击这样的像素，查看产生它的语句。

## src/app/compact.rs

compact-menu = 菜单
compact-keys = 快捷键（?）
compact-stage = 阶段
compact-picture = 画面
compact-code = 代码

## src/app/editor/file.rs

file-cannot-read = 无法读取 { $file }：{ $why }
file-not-saved = 未保存：{ $why }
file-changed-since-opened = { $file } 在打开之后已在磁盘上被修改：覆盖它，还是从磁盘重新载入并丢弃这些编辑？
file-no-file = 没有文件
file-no-text-to-edit = { $source }：没有可编辑的文本

## src/app/editor/file_actions.rs

file-actions-undo = ↶ 撤销
file-actions-redo = ↷ 重做
file-actions-save-as-a-new-lesson = 另存为新课程 ↓
file-actions-save = 保存
file-actions-save-download = 保存（下载）
file-actions-a-built-in-lesson-is = 内置课程不会被修改：在下面把它新建为你自己的课程文件（新建课程，从本课程开始）。
file-actions-ctrl-s-the-file-is = Ctrl+S：文件要么完整写入，要么不写
file-actions-unsaved = ● 未保存
file-actions-unsaved-changes-kept-in-a = 有未保存的修改，保存（Ctrl+S）之前已在文件旁保存恢复副本。
file-actions-saved = 已保存
file-actions-unsaved-changes-to-this-lesson = 上次编辑这个课程时有未保存的修改，已保留。
file-actions-restore-them = 恢复这些修改
file-actions-restored-save-keeps-them-undo = 已恢复：保存即保留，撤销即放弃。
file-actions-discard-them = 丢弃
file-actions-the-file-changed-on-disk = 编辑期间，文件在磁盘上被修改了。
file-actions-overwrite-it-with-my-edits = 用我的修改覆盖它
file-actions-load-it-from-disk-undo = 从磁盘载入（撤销可找回我的修改）
file-actions-loaded-from-disk = 已从磁盘载入。
file-actions-saved-to = 已保存：{ $file }
file-actions-not-done-the-lesson-would = 未执行：这样改动后课程将无法通过检查（某一步的参数可能依赖它之前的步骤）：
file-actions-the-lesson-does-not-pass = 课程无法通过检查；在修正之前继续播放上一个正确的版本：

## src/app/editor/new.rs

new-new-lesson = 新建课程…
new-from-the-scene-on-screen = 从屏幕上的场景开始，当前画面作为第一步
new-from-a-built-in-lesson = 从一个内置课程开始：
new-from-a-mesh-of-your = 从你自己的网格开始（.obj；也可以把文件拖到窗口上）：
new-write-it-to = 写入：
new-name = 名称：
new-make-the-lesson = 新建课程
new-nothing-on-screen = 屏幕上没有可作为起点的内容
new-choose-a-built-in-lesson = 请选择一个内置课程
new-name-the-mesh-file = 请写出网格文件（.obj）的名字
new-from-a-mesh-dropped = 从拖放到页面上的网格开始（.obj）：
new-drop-the-mesh = 请先把网格文件（.obj）拖放到页面上
new-exists-already = { $file } 已经存在：请换一个名字（原文件保持不变）
new-cannot-create = 无法创建 { $dir }：{ $why }
new-made = 新课程：{ $source }
new-no-lesson-open = 没有打开的课程

## src/app/editor/screen.rs

screen-update-step = 用屏幕内容更新第 { $step } 步
screen-new-step-words = 新的第 { $step } 步：文字
screen-add-as-step = ＋ 添加为第 { $step } 步
screen-what-is-on-screen = 屏幕上的内容
screen-the-stage-buffer-layout-overlays = 阶段、缓冲、布局、叠加层、所检查的像素、选中的顶点，以及本步骤开始以来改动过的每个参数。编辑器打开时拖动滑块即可录制动画。
screen-no-parameter-changed = 没有改动参数。
screen-its-words-shaders-and-exercise = 保留它的文字、着色器和练习
screen-title = 标题
screen-narration = 讲解
screen-seconds-from-the-first-value = 从起始值到结束值的秒数
screen-not-an-animation = 不作为动画

## src/app/editor/window.rs

window-steps-deleted = 自上次保存以来删除了 { $count } 步
window-step-label = 第 { $step } 步：
window-lesson-editor = 课程编辑器
window-close-the-editor-r = 关闭编辑器（R）
window-a-built-in-lesson-is = 内置课程不能直接修改。先把它新建为你自己的课程（见下方“新建课程”，从本课程开始），再在那里录制、撰写和调整步骤。
window-open-a-lesson-to-edit = 打开一个课程即可编辑它，或在下面新建一个。
window-steps = 步骤
window-changed-since-the-last-save = ● 自上次保存以来有改动
window-earlier = ▲ 前移
window-later = ▼ 后移
window-duplicate = 复制
window-delete = 删除

## src/app/editor/words.rs

words-of-step = 第 { $step } 步的文字
words-the-lesson-s-title-and = 课程的标题与简介
words-title = 标题
words-summary = 简介
words-narration = 讲解
words-question-optional = 思考题（可选）
words-answer-optional = 答案（可选）
words-worded-english = 已写好：English、中文
words-still-needs = 还缺少：

## src/app/export_task.rs

export-task-handout-saved = 讲义已保存：{ $file }
export-task-exported-to = 已导出到 { $dir }：{ $files }
export-task-your-work-saved = 你的作业已保存：{ $file }（{ $steps } 个步骤有作业）

## src/app/platform.rs

platform-the-browser-refused-the-download = 浏览器拒绝了下载：{ $why }

## src/app/layout.rs

layout-resize-panel = 调整面板大小：{ $panel }

## src/app/library.rs

library-could-not-be-opened = 无法打开 { $file }；已打开的内容继续运行：
library-not-a-kind-pipelens-opens = { $name }：pipelens 打开课程和场景（.toml）、着色器（.vert、.frag、.glsl）、网格（.obj）和纹理（.png、.jpg），不打开 .{ $extension } 文件
library-not-text = 该文件不是 UTF-8 文本：请拖入课程或场景的 .toml 文件
library-shader-not-text = { $name } 不是 UTF-8 文本
library-a-texture-on-the-desktop = { $name }：纹理由引用它的课程（texture = "{ $name }"）从课程所在的文件夹读取：请改为打开那节课程
library-texture-kept = 已保留 { $name }，供引用它的课程使用（texture = "{ $name }"）：现在拖放这样的课程，或把课程和它的纹理一起拖放。
library-cannot-read-the-file = 无法读取文件：{ $why }
library-lessons = 课程
library-all-right = 全对
library-d-n-questions-you-answered = d/n：需要填写数值的思考题中你已答对的数目
library-edit-this-lesson-or-make = 编辑本课程或新建课程…（R）
library-record-what-is-on-screen = 把屏幕上的内容录制为步骤，用两种语言撰写文字，调整顺序，保存文件
library-your-own-lesson-or-scene = 自己的课程或场景：把它的 .toml 文件拖放到窗口上；保存后自动重新加载。
library-your-own-lesson-or-scene-2 = 自己的课程或场景：把它的 .toml 文件连同它用到的网格（.obj）和纹理（.png、.jpg）一起拖放到页面上；单独拖放的网格会成为一节新课程。网页无法监视文件：修改后请重新拖放。
library-open-another-built-in-lesson = 打开另一个内置课程

## src/app/platform.rs

platform-pipelens-the-keys-typed-into = pipelens：输入应用的按键

## src/app/step_panels.rs

step-panels-shaders-glsl = 着色器（GLSL）

## src/app/toolbar.rs

toolbar-view = 视图 ▾
toolbar-observer-view = 观察者视图
toolbar-the-scene-seen-from-outside = 从外部看场景，并显示相机的视锥和光源。
toolbar-side-by-side = 并排对比
toolbar-off = 关
toolbar-render-the-scene-with-different = 用不同设置渲染场景并并排显示，附亮度剖面曲线。

## src/app/views/alt.rs

alt-name-colon = ：

## src/app/views/answer.rs

answer-type-the-value = 填入数值
answer-type-the-components = 填入 { $n } 个分量
answer-type-the-values = 填入 { $n } 个数值
answer-type-the-matrix = 逐格填入 { $rows }×{ $columns } 矩阵
answer-prompt = { $what }（每项误差 { $tolerance } 以内）：
answer-a-number-or-an-expression = 数值或算式：0.866、sqrt(3)/2、2*pi/3、1/4
answer-check = 检查
answer-compare-with-the-expected-value = 与期望值比较（回车）
answer-answered-right-before = 之前已答对

## src/app/views/breakpoints.rs

breakpoints-line = 行
breakpoints-at-hit = 在第
breakpoints-every = 每次
breakpoints-stop-only-the-n-th = 只在运行第 n 次到达此行时停下（在循环中即第 n 次迭代）；0 表示每次都停。
breakpoints-where = 条件
breakpoints-find-in-the-frame = 在整帧中查找
breakpoints-the-first-fragment-reading-the = 从画面顶部读起，第一个在此行之后条件成立的片元：检查它，并在此行显示它的运行过程。
breakpoints-the-condition-cannot-be-read = 无法在此处读取该条件：
breakpoints-remove-this-breakpoint = 删除此断点
breakpoints-holds-at-no-fragment-of = 在此帧中没有任何片元在该行之后成立。
breakpoints-is-not-a-condition-a = 不是条件（bool）：请写一个比较，例如 diffuse <= 0.0。

## src/app/views/compare.rs

compare-rendering-the-comparison = 正在渲染对比…
compare-compared-image = 对比图像：{ $caption }

## src/app/views/debugger.rs

debugger-this-is-the-run-s = 这已是运行的第一步。
debugger-no-breakpoint-stops-the-run = 此步之前没有断点使运行停下。
debugger-no-breakpoint-is-set-click = 尚未设置断点：单击行号，或在某行按 F9。
debugger-no-breakpoint-stops-the-rest = 运行的其余部分没有断点使它停下。
debugger-put-the-text-cursor-on = 请先把文本光标放在某一行上。
debugger-the-rest-of-this-run = 运行的其余部分不会到达光标所在行。
debugger-this-step-is-in-main = 此步在 main 中：没有可返回的调用者。
debugger-this-is-the-run-s-2 = 这已是运行的最后一步。
debugger-step = 第
debugger-line = 行
debugger-steps-f10-steps-through-them = 步：按 F10 逐步执行
debugger-watch = 监视
debugger-after-line = 在行
debugger-variables-at-this-step = 此步的变量
debugger-debugger-click-a-pixel-of = 调试器：单击画面中的一个像素；它的片元的运行在这里逐步执行（F10）。
debugger-debugger-select-a-vertex-a = 调试器：选择一个顶点（在几何视图中单击，或在顶点表中选一行）；它的运行在这里逐步执行（F10）。
debugger-fragment = 片元
debugger-several-fragments-reached-this-pixel = 有多个片元到达此像素（在此相交的三角形，或被 discard 剥离的层）：选择跟随哪一个。

## src/app/views/exercise.rs

list-separator = 、
sentence-separator = { "" }
exercise-drawing-pipelens-own-frame = 正在绘制 pipelens 自带的画面…
exercise-pipelens-own = pipelens 自带
exercise-difference = 差异：
exercise-colour = 颜色
exercise-coverage = 覆盖
exercise-depth = 深度
exercise-another-triangle = 另一个三角形
exercise-exercise = 练习
exercise-write-your-code-in-the = 在着色器面板（S 键）中编写代码：边写边运行，你的曲线与 pipelens 的 b(t) 逐点比较。
exercise-write-your-code-in-the-2 = 在着色器面板（S 键）中编写代码：边写边运行，你的曲面与 pipelens 的 b(u, v) 逐点比较。
exercise-write-your-code-in-the-3 = 在着色器面板（S 键）中编写代码：边写边运行，画面与 pipelens 自带的逐像素比较。
exercise-inspect-the-first-wrong-vertex = 检查第一个错误的顶点
exercise-selects-its-row-of-the = 选中它在顶点表中的那一行：检查器显示你的顶点着色器对它的运行过程。
exercise-inspect-the-first-wrong-pixel = 检查第一个错误的像素
exercise-selects-it-the-inspector-shows = 选中它：检查器并列显示你的着色器在该处的运行过程和 pipelens 自带的推导。
exercise-passed-before = 之前已通过。

## src/app/views/geometry/cards.rs

cards-near-plane = 近平面
cards-far-plane = 远平面
cards-light = 光源
cards-showing-triangles = 显示三角形

## src/app/views/geometry/mod.rs

geometry-geometry-view = 几何视图
geometry-nothing-to-show-in-this = 此空间中没有可显示的顶点
geometry-front-view = 正视图
geometry-reset-view = 重置视角
geometry-or-double-click-the-picture = 或双击画面。
geometry-legend = 图例
geometry-legend-what = 图中各颜色与虚线的含义：点按以显示或隐藏。
geometry-normals = 法线
geometry-each-vertex-s-normal-n = 每个顶点在世界空间中的法线 n，即光照所用的法线（n_world = (M^(−1))^T·n）。
geometry-replay-transition = ▶ 重播变换
geometry-space = 空格键

## src/app/views/glsl_keys.rs

code-keys-types = 在光标处输入 { $key }

## src/app/views/inspector/matrices.rs

matrices-what-this-stage-applies = 本阶段使用的矩阵
matrices-games101-s-m-viewport-maps = GAMES101 的 M_viewport 对 x、y 的变换相同而 z 保持不变；OpenGL（以及 pipelens）还把 z 从 [−1, 1] 映射到 z_w ∈ [0, 1]。（笔记中把该矩阵误标为 M_{"{"}persp→ortho{"}"}。）
matrices-other-matrices = 其他矩阵
matrices-object = 物体
matrices-the-same-projection-in-games101 = GAMES101 记法下的同一投影（n = −near，f = −far）：
matrices-m-ortho-m-persp-ortho = M_ortho·M_{"{"}persp→ortho{"}"} = −Z·P，Z = diag(1, 1, −1, 1)：除法后 x、y 相同；NDC 的 z 取反（近平面 → +1）。
matrices-m-ortho-z-ortho-with = M_ortho = Z·Ortho，Z = diag(1, 1, −1, 1)：NDC 的 z 取反（近平面 → +1）。
matrices-matrix-stack-depth-first = 矩阵栈（深度优先遍历）

## src/app/views/inspector/mod.rs

inspector-matrices = 矩阵
inspector-vertices = 顶点表
inspector-pixel = 像素

## src/app/views/inspector/pixel.rs

pixel-click-a-pixel-in-a = 在像素视图（光栅化、深度、着色、纹理、输出）中单击一个像素，查看到达它的每个片元以及它的颜色是如何得到的。
pixel-pixel = 像素
pixel-triangle = 三角形
pixel-coverage = 覆盖
pixel-depth-mean-of-samples = 深度（采样平均）
pixel-colour = 颜色
pixel-how-the-fragment-got-here = 片元如何到达这里（以及 pipelens 自带着色会得到什么）：
pixel-no-fragment-owns-this-pixel = 没有片元拥有此像素：它保持背景色。
pixel-every-fragment-that-reached-the = 到达此像素的每个片元
pixel-none = 没有。
pixel-your-inside-covers-none-of = 你的 inside() 没有覆盖这些片元的任何采样点（上面的采样点是 pipelens 自己的边测试给出的）。
pixel-every-fragment-failed-the-depth = 所有片元都未通过深度测试。
pixel-explain-this-pixel = 解释这个像素
pixel-fragment = 片元
pixel-visible = {"  "}√ 可见
pixel-a-piece-of-a-clipped = （被裁剪三角形的一部分）
pixel-samples = 采样点：
pixel-not-covered = 未覆盖
pixel-covered-passed-the-depth-test = 被覆盖，通过深度测试：
pixel-covered-failed-the-depth-test = 被覆盖，未通过深度测试：
pixel-on-an-edge-the-top = {"*"} 在边上：由左上填充规则决定

## src/app/views/inspector/rotation.rs

rotation-the-same-rotation-r-n = 同一个旋转 R(n, θ) 的另外两种算法
rotation-rodrigues-formula-n-the-cross = Rodrigues 公式，N 是 n 的叉乘矩阵：
rotation-w-x-y-z-q = （w, x, y, z）；−q 表示同一个旋转。它的矩阵：
rotation-halfway-along-the-shortest-arc = 沿最短弧走到一半，即绕同一轴旋转 θ/2。
rotation-between-two-orientations-slerp = 两个朝向之间：球面线性插值 slerp
rotation-the-first-axis = 第一个轴
rotation-the-second-axis = 第二个轴
rotation-0-slerp-takes-q-the = {" "}< 0：slerp 改用 −q₁，同一个旋转，走较短的一侧
rotation-the-turn-from-one-to = 两个朝向之间相差的转角
rotation-weights = 权重
rotation-about = 绕轴

## src/app/views/inspector/shader_trace.rs

shader-trace-your-fragment-shader-at-this = 你的片元着色器在此像素
shader-trace-it-did-not-run-here = 它没有在这里运行：没有带着色器的物体的三角形覆盖此像素。
shader-trace-pixels-of-this-frame-came = 个像素的结果为 NaN 或无穷大（画成黑色）。
shader-trace-fragment = 片元
shader-trace-triangle = 三角形
shader-trace-sample-s = 个采样
shader-trace-received-interpolated-across-the-triangle = 收到的输入（在三角形上插值）
shader-trace-ran-statement-by-statement = 逐条语句的执行
shader-trace-discarded-what-lies-behind-shows = → 被丢弃（discard）：显示其后方的表面。
shader-trace-your-vertex-shader-at-vertex = 你的顶点着色器在顶点
shader-trace-received-its-attributes = 收到的输入（它的属性）
shader-trace-wrote = 输出
shader-trace-line = 行

## src/app/views/inspector/vertices.rs

vertices-model = 模型
vertices-world = 世界
vertices-eye = 相机
vertices-clip-x-y-z-w = 裁剪 (x, y, z, w)
vertices-window = 屏幕
vertices-spaces = 空间：
vertices-click-a-row-to-highlight = 单击一行，在所有视图中高亮该顶点；在视图中单击顶点可找到它所在的行。
vertices-vertex = 顶点
vertices-object = 物体

## src/app/views/lesson.rs

lesson-fold-the-narration-away = 收起讲解
lesson-fold-the-narration-away-n = 收起讲解（N）
lesson-predict-first-the-question-below = 先预测（见下方思考题），再按空格键观看。
lesson-animation-line = ▶ { $param }：{ $from } → { $to }
lesson-question = 思考题
lesson-hide-the-answer = 隐藏答案
lesson-show-the-answer = 显示答案

## src/app/views/matrix.rs

matrix-grid = 4×4 矩阵，按行：{ $rows }
matrix-grid-row = 第 { $row } 行：{ $values }
matrix-factors = 分解

## src/app/views/observer.rs

observer-observer-the-scene-seen-from = 观察者：从外部看到的场景，带有观察相机、视锥和光源
observer-rendering-the-observer = 正在渲染观察者视图…
observer-observer = 观察者 ▾
observer-the-scene-from-outside-drag = 从外部看场景：拖动旋转，滚轮缩放。
observer-camera-frame-u-v-n = 相机标架 u, v, n
observer-clipped-polygons = 裁剪后的多边形
observer-frustum-sides = 视锥侧棱
observer-near-plane = 近平面
observer-far-plane = 远平面
observer-lights = 光源

## src/app/views/own_uniforms.rs

own-uniforms-tip = uniform { $kind } { $name }（第 { $line } 行）：范围 { $lo }..{ $hi } 和初值来自其后的注释 `// 最小..最大 = 初值`；课程用 "uniforms.{ $name }" 设置它
own-uniforms-your-uniforms = 你的 uniform

## src/app/views/params/lighting.rs

lighting-i-the-light-s-intensity = I：光源在 RGB 各通道的强度，L = k·I·…
lighting-intensity-i = 强度 I
lighting-f-att-1-a-b = f_att = 1/(a + b·d + c·d²)
lighting-l-position-p-position-p = l = (position − p)/|position − p|
lighting-l-direction-direction-the-light = l = −direction/|direction|：光沿这个方向传播
lighting-direction = 方向
lighting-position = 位置
lighting-the-cone-s-axis = 圆锥的轴
lighting-axis = 锥轴
lighting-cutoff = 截止角
lighting-f-spot-cos-e-inside = 截止角以内 f_spot = (cos φ)^e，以外为 0
lighting-f-spot-cos-e-a = f_spot = (cos φ)^e：e 越大，圆斑向边缘衰减越快
lighting-material = 材质
lighting-ambient-l-a-k-a = 环境光：L_a = k_a·c·I_a
lighting-diffuse-l-d-k-d = 漫反射：L_d = k_d·c·(I/r²)·max(0, n·l)
lighting-specular-l-s-k-s = 高光：L_s = k_s·(I/r²)·max(0, n·h)^p
lighting-shininess-p = 高光指数 p
lighting-p-in-n-h-p = (n·h)^p（Blinn-Phong）或 (r·v)^p（Phong）中的 p：越大，高光越小越锐利

## src/app/views/params/mod.rs

params-camera = 相机
params-lookat-eye-at-up-n = LookAt(eye, at, up)：n = (eye − at)/|eye − at|，u = up × n/|up × n|，v = n × u
params-eye = 视点
params-at = 参考点
params-up = 上方向
params-projection = 投影
params-rasterizer-settings = 光栅化设置
params-lights = 光源
params-joint-angles = 关节角
params-objects = 物体
params-m-t-rz-ry-rx = M = T·Rz·Ry·Rx·S
params-translate = 平移
params-rotate = 旋转 °
params-scale = 缩放
params-q-axis = q₀ 旋转轴
params-axis-n = 旋转轴 n
params-r-n-cos-i-1 = R(n, θ) = cos θ·I + (1 − cos θ)·n·n^T + sin θ·N；q = (cos(θ/2), sin(θ/2)·n)
params-q-axis-2 = q₁ 旋转轴
params-slerp-q-q-t-sin = slerp(q₀, q₁, t) = sin((1 − t)Ω)/sin Ω·q₀ + sin(tΩ)/sin Ω·q₁，cos Ω = q₀·q₁：t = 0 为 q₀，t = 1 为 q₁，其间匀角速度转动
params-angle = 转角 θ
params-perspective = 透视 Perspective
params-frustum = 视见体 Frustum
params-ortho = 正交 Ortho
params-projection-2 = 投影
params-vertical-field-of-view-top = 垂直视场角。top = near·tan(fovy/2)，right = top·aspect（复习讲义中的 near·tan(fovy) 是笔误）。
params-aspect-from-the-viewport = 宽高比取视口的
params-the-near-rectangle-l-r = 近平面矩形 [l, r] × [b, t]
params-near = 近 near{" "}
params-distance-to-the-near-plane = 到近平面 z = −near 的距离。near 过小会浪费深度精度：z_ndc = (f+n)/(f−n) − 2fn/((f−n)·d)。
params-far = 远 far{" "}
params-distance-to-the-far-plane = 到远平面 z = −far 的距离。
params-viewport = 视口
params-samples-per-pixel = 每像素采样数
params-msaa-coverage-and-depth-per = MSAA：每个采样点单独计算覆盖与深度，每个像素每个三角形只着色一次；4× 使用旋转网格。
params-culling = 面剔除
params-none = 无
params-back = 背面
params-front = 正面
params-front-faces-are-counter-clockwise = 屏幕上逆时针的面为正面。
params-depth-test = 深度测试
params-shade-every-sample-ssaa = 每个采样点着色（SSAA）
params-off-multisampling-shades-once-per = 关：多重采样每个像素每个三角形在像素中心着色一次。开：超采样在每个采样点各自着色。
params-perspective-correct-interpolation = 透视校正插值
params-your-shaders-draw-the-picture = 画面由你的着色器绘制：下面的着色频率与镜面项不改变画面；它们决定着色器面板中“pipelens 自带”写出的着色器。
params-shading = 着色频率
params-unlit = 无光照
params-flat = 平面
params-flat-once-per-face-gouraud = 平面：每个面一次。Gouraud：按顶点计算，颜色插值。Phong：法向插值，按像素计算光照。
params-specular = 镜面项
params-texture-filter = 纹理过滤
params-nearest = 最近邻
params-bilinear = 双线性
params-nearest-level = 最近层
params-mipmap = Mipmap
params-trilinear = 三线性
params-summed-area-table = 求和面积表
params-log-max-uw-vh-x = λ = log₂ max(|∂(uw, vh)/∂x|, |∂(uw, vh)/∂y|)：纹素大小与像素相当的层级。
params-anisotropy = 各向异性
params-up-to-n-samples-along = 沿覆盖区域（足迹）长轴最多取 N 个样本；λ = log₂(长轴/N)。
params-mip-bias = mip 偏移
params-base-b-y = 支架 θ_b (y)
params-lower-arm-la-z = 下臂 θ_la (z)
params-upper-arm-ua-z = 上臂 θ_ua (z)
params-torso-y = 躯干 (y)
params-head-y = 头 (y)
params-left-upper-arm = 左上臂
params-left-lower-arm = 左下臂
params-right-upper-arm = 右上臂
params-right-lower-arm = 右下臂
params-left-upper-leg = 左大腿
params-left-lower-leg = 左小腿
params-right-upper-leg = 右大腿
params-right-lower-leg = 右小腿
params-the-joint-s-rotation-every = 关节旋转：树中其下的所有部件随之运动（M ← M·local）。
params-less-gl-less = < 更近 (GL_LESS)
params-less-or-equal = ≤ 更近或相等
params-greater = > 更远
params-greater-or-equal = ≥ 更远或相等
params-always-painter-s-order = 总是通过（画家顺序）

## src/app/views/pixels/depth_and_mips.rs

depth-and-mips-eye-distance-d-near-far = 到视点的距离 d（近 → 远）
depth-and-mips-window-depth-z-w = 窗口深度 z_w
depth-and-mips-curve-legend = z_w(d)，近 { $near }，远 { $far }
depth-and-mips-depths-in-the-image = 图像中的深度
depth-and-mips-grey-ramp-black-white = 灰度范围：黑 → 白
depth-and-mips-mip-pyramid = mipmap 金字塔
depth-and-mips-framed-the-level-read-at = 框出：所检查像素读取的层级，青色为其覆盖区域

## src/app/views/pixels/draw.rs

draw-overlays-first-20-000-shapes = 叠加层：只显示前 20000 个图形
draw-mip-level = mipmap 层级
draw-top-left = （上/左边）

## src/app/views/pixels/hover.rs

hover-after-line = 第 { $line } 行之后
hover-pixel = 像素
hover-coverage = 覆盖
hover-depth = 深度
hover-eye-distance = 相机距离
hover-primitive = 图元
hover-perspective-correct = 透视校正
hover-affine = 仿射
hover-the-line-did-not-run = 这里没有执行该行
hover-click-to-inspect = 单击查看详情
hover-no-object-of-this-scene = 此场景中没有物体带纹理：没有可显示的纹理查询。
hover-rendering-this-buffer = 正在渲染此缓冲…

## src/app/views/pixels/mod.rs

pixels-triangle-edges = 三角形边
pixels-bounding-boxes = 包围盒
pixels-buffer = 缓冲
pixels-sample-points = 采样点
pixels-zoom-in-to-see-each = 放大后显示每个像素的采样位置：被覆盖时为实心。采样模式是标准模式：Direct3D 公布的数值按 y 向上使用，与 Mesa 的 llvmpipe 相同（OpenGL 不规定采样位置），所以这里的 4× 模式是 Direct3D 图示的上下镜像。
pixels-mip-pyramid = mipmap 金字塔
pixels-every-level-of-the-texture = 同时显示纹理的所有层级：每一层是上一层的 2×2 盒式滤波。
pixels-variable-picture = 变量图
pixels-the-shader-panel-s-watch = 着色器面板的整帧监视（或开销视图）画在这里，代替缓冲：数值用色带表示，深蓝最小、黄色最大；条件成立处为黄色；灰色棋盘格是没有片元执行该行之处。悬停可看某个像素的值。
pixels-fit = 适应窗口
pixels-zoom-to-fit-double-click = 缩放以适应（双击图像）
pixels-linear-eye-distance = 线性：相机距离
pixels-z-w-is-not-linear = z_w 与距离不成线性：d = 2fn/((f+n) − z_ndc·(f−n))。[0, 1] 的大部分分给了视锥体的近处。
pixels-black-at = 黑：
pixels-white-at = 白：
pixels-auto-range = 自动范围
pixels-pixel-view = 像素视图

## src/app/views/shader.rs

shader-debugger = 调试器
shader-apply = 应用
shader-compile-and-draw-with-these = 编译并用这些着色器绘制（Ctrl+Enter）
shader-save = 保存
shader-writes-shader-vert-and-shader = 把 shader.vert 和 shader.frag 写入导出文件夹；当前步骤运行 inside 或 depth_test 函数时，还写入 inside.glsl 或 depth_test.glsl（在浏览器中：下载它们）。课程用 shader = {"{"} vertex = "shader.vert", fragment = "shader.frag", inside = "inside.glsl" {"}"} 读取它们。
shader-saved = 已保存：
shader-source = ：源代码
shader-back-to-your-code = ← 回到你的代码
shader-puts-back-the-code-you = 恢复被 pipelens 自带着色替换之前你的代码。
shader-pipelens-own = pipelens 自带
shader-start-again-from-pipelens-own = 从 pipelens 针对当前设置的自带着色（GLSL 写成）重新开始（无光照；平面；Gouraud；Phong 着色，n·h 或 r·v；凹凸或法线贴图）：画出的像素相同。平面或 Gouraud 着色配 r·v、凹凸贴图配 r·v 以及镜面没有对应的着色器：此时用逐像素 Blinn-Phong。你的代码仍可一键恢复（回到你的代码）。
shader-the-rasterizer-calls-it-for = 光栅化器对三角形包围盒内的每个采样点调用它：p 是采样点，a、b、c 是顶点（窗口像素坐标，y 向上，逆时针）。它代替 pipelens 的边函数 E_i(p) ≥ 0 及左上规则来决定覆盖。
shader-the-rasterizer-calls-it-for-2 = 光栅化器对三角形覆盖的每个采样点调用它：z 是三角形在该处的窗口深度（在 [0, 1] 内），stored 是深度缓冲中已存的值（尚未绘制处为 1）。返回 true 则把 z 和该三角形写入采样点。它代替设置中的深度比较（less：z < stored）。
shader-a-b-zier-curve-s = 贝塞尔曲线的绘制对曲线上的每个点调用它（t 从 0 到 1 取 161 个值）：p0 … p3 是控制点，在曲线所在平面内。它代替 pipelens 自己的 b(t) = Σ B_i³(t)·P_i。
shader-the-shadow-pass-calls-it = 阴影绘制每帧调用它一次：light 是点光源相对于接收阴影的平面的位置，平面取为 y = 0。每个阴影物体都用它代替 pipelens 的 M_shadow = T(l)·M_p·T(−l) 绘制；它的任何正倍数投下同样的阴影。
shader-a-b-zier-patch-s = 贝塞尔曲面片的绘制对曲面网格的每个顶点调用它（(u, v) 在 0 到 1 之间取 25 × 25 个值）：p[4i + j] 是控制点 P_ij，第 i 行沿 v，第 j 列沿 u。它代替 pipelens 自己的 b(u, v) = Σ Σ B_i³(v)·B_j³(u)·P_ij；曲面仍用 pipelens 的精确法线。
shader-inside-test = 内部测试 inside
shader-depth-test = 深度测试 depth_test
shader-de-casteljau = de Casteljau 算法
shader-shadow-matrix = 阴影矩阵 shadow_matrix
shader-b-zier-patch = 贝塞尔曲面片 bezier_patch
shader-vertex-shader = 顶点着色器
shader-fragment-shader = 片元着色器
shader-compiles-but-the-run-stopped = 可以编译，但运行中止；画面保持上一次成功的结果：
shader-compiled-the-pipeline-calls-these = 已编译：管线调用这些函数来代替它自己的实现（把鼠标停在标签上可看到何时调用、代替什么）；着色仍由 pipelens 完成。
shader-compiled-the-picture-is-drawn = 已编译：画面由这些着色器绘制。
shader-the-picture-is-drawn-by = 画面由 pipelens 自带的着色绘制：按“应用”（Ctrl+Enter）或编辑后，改用这些着色器绘制。
shader-does-not-compile-the-last = 无法编译：画面保持上一次成功的结果。

## src/app/views/watch_list.rs

watch-list-undeclared-input = 它读取了 `{ $name }`，而你的着色器没有声明它：这一帧没有传入它
watch-list-not-readable = 无法在第 { $line } 行之后读取：{ $why }
watch-list-no-run-is-kept-here = 这里没有保存的运行：请检查一个像素或选择一个顶点
watch-list-watch-list = 监视列表
watch-list-after-line = 在此行之后：
watch-list-take-it-off-the-list = 从列表中移除
watch-list-up-to-this-step-the = 到此步为止，这次运行尚未执行此行
watch-list-add = 添加：
watch-list-an-expression-e-g-dot = 表达式，例如 dot(n, l)
watch-list-any-expression-of-this-shader = 此着色器中的任意表达式，在所示运行中于此步所在行之后读取；按 Enter 添加。
watch-list-watch = ＋ 监视

## src/app/views/watch_picture.rs

watch-picture-watch-over-the-frame = 整帧监视：
watch-picture-any-expression-of-your-fragment = 片元着色器中的任意表达式，在该行执行之后读取，每个像素一个值：数值用色带表示（深蓝最小，黄色最大），向量显示为颜色或某一分量，条件显示其成立之处。灰色棋盘格：那里没有片元执行该行。
watch-picture-any-expression-of-your-vertex = 顶点着色器中的任意表达式，在每个顶点执行该行之后读取，再像 varying 一样送到每个像素：在三角形上用透视校正的权重插值，(Σ λᵢ·aᵢ/wᵢ)/(Σ λᵢ/wᵢ)；int 与 bool 按 GLSL 的规定 flat 传递，取三角形最后一个顶点的值。数值用色带表示（深蓝最小，黄色最大），向量显示为颜色或某一分量，条件显示其成立之处。灰色棋盘格：那里三角形有顶点没有执行该行。
watch-picture-e-g-dot-n-l = 例如 dot(n, l) < 0.0
watch-picture-after-line = 在此行之后：
watch-picture-the-step-s = 当前步的行
watch-picture-watch-after-the-line-of = 在调试器当前步所在行之后监视。
watch-picture-show = 显示
watch-picture-stop = 停止
watch-picture-cost-the-steps-each-fragment = 开销：每个片元执行的步数
watch-picture-at-each-pixel-how-many = 每个像素上，它的片元执行了片元着色器的多少步（调试器逐步执行的那些步：赋值、分支、循环判断与迭代、调用、返回）：循环次数多或分支工作多的地方更亮。深蓝最少，黄色最多。
watch-picture-cannot-watch = 无法监视：
watch-picture-no-triangle-of-this-frame = 此帧没有哪个三角形的三个顶点都执行了该行。
watch-picture-no-fragment-of-this-frame = 此帧没有片元执行该行。
watch-picture-steps = 步
watch-picture-no-fragment-of-yours-here = 这里没有你的片元
watch-picture-a-corner-of-the-triangle = 这里三角形有顶点没有执行该行
watch-picture-the-line-did-not-run = 这里没有执行该行
watch-picture-pixel = 像素
watch-picture-after-line-2 = 在行
watch-picture-as-colour = 显示为颜色
watch-picture-true = 成立
watch-picture-false = 不成立
watch-picture-first-where-it-holds = 第一个成立之处 ▶
watch-picture-inspects-the-first-pixel-where = 检查从画面顶部读起第一个条件成立的像素，并在被监视的行显示它的运行过程：在整帧上的条件断点。
watch-picture-x-red-y-green-z = x → 红，y → 绿，z → 蓝，各自截取到 [0, 1]
watch-picture-not-run = 未执行

## src/app/window.rs

window-parameters = 参数
window-rendering = 渲染中…
window-title-lesson-step = pipelens — { $lesson } — 第 { $step }/{ $steps } 步

## src/bench/handouts.rs

handouts-en = zh

## src/cli/grade.rs

grade-cannot-be-read = 无法读取 { $file }：{ $why }
grade-too-large = { $name } 有 { $megabytes } MB；着色器最多 { $kilobytes } KB：不予评分
grade-not-text = { $name } 不是文本（含有非 UTF-8 的字节）
grade-outside-folder = { $name } 是指向作业文件夹之外的链接：未读取
grade-nothing = { $file } 中没有 shader.vert、shader.frag 或函数文件（{ $functions }）
grade-not-work = { $file }：不是 pipelens 写的作业文件（{ $why }）
grade-other-lesson = { $file } 是课程 { $lesson } 的作业，不是这一课的
grade-no-work-at = { $file } 中没有第 { $step } 步的代码
grade-summary = { $handins } 份作业，{ $checks } 项检查，{ $passed } 项通过
grade-gradescope-step = 第 { $step } 步：{ $title }
grade-gradescope-output = { $total } 个练习步骤中通过 { $passed } 个，每个都与 pipelens 自带的逐像素比较。
grade-pipelens-failed-while-checking-this = pipelens 在检查这份作业时出错（这是 pipelens 的缺陷，不是作业的问题）：请报告
grade-student = 学生
grade-step = 步骤
grade-passed = 通过
grade-matching = 一致
grade-feedback = 反馈
grade-yes = 是
grade-no = 否

## src/export/handout_exercise.rs

handout-exercise-the-shaders-this-step-runs = 本步骤运行的着色器（黄底：与上一步相比改动的行）：
handout-exercise-pipelens-own-what-your-code = pipelens 自带的结果：你的代码要画出的画面

## src/export/mod.rs

export-cannot-create-the-folder = 无法创建文件夹 { $dir }
export-cannot-write = 无法写入 { $file }

## src/export/lesson.rs

lesson-exercise = 练习：
lesson-the-debugger-at-pixel = 调试器：像素
lesson-step-not-drawn = 第 { $step } 步：{ $why }
lesson-step-watch = 第 { $step } 步的监视

## src/export/picture.rs

picture-watch-title = 第 { $line } 行之后的 { $expression }
picture-watch-holds = 成立处为黄色，不成立处为深蓝色
picture-watch-range = 深蓝 { $lo } 到黄色 { $hi }
picture-watch-vector = 向量显示为颜色
picture-watch-legend-fragment = 第 { $line } 行之后的 { $expression }：{ $said }；灰色棋盘格处没有片元执行该行
picture-watch-legend-vertex = 顶点着色器第 { $line } 行之后的 { $expression }，经三角形上插值：{ $said }；灰色棋盘格处三角形有顶点没有执行该行
picture-mip-level = mipmap 层级

## src/observer.rs

observer-eye = 视点

## src/spaces.rs

spaces-object-coordinates = 模型坐标
spaces-world-coordinates = 世界坐标
spaces-eye-coordinates-camera-at-the = 相机坐标：相机在原点，朝向 −z
spaces-clip-coordinates-x-y-z = 裁剪坐标（齐次点的 x, y, z）
spaces-normalized-device-coordinates-the-canonical = 规范化设备坐标：规范立方体 [−1, 1]³
spaces-window-coordinates-0-w-0 = 屏幕坐标：[0, W] × [0, H] × [0, 1]

## src/vocabulary/alt_text.rs

alt-text-comma = ，
alt-text-nothing-drawn = ：没有绘制任何物体。
alt-text-list-comma = 、
alt-text-colon = ：
alt-text-full-stop = 。
alt-text-ellipsis = ；……

## src/vocabulary/buffers.rs

buffers-shown-brighter = { $name }放大 ×{ $gain } 显示：亮度是其数值的 { $gain } 倍
buffers-colour = 颜色
buffers-depth = 深度
buffers-coverage = 覆盖率
buffers-primitive-id = 图元编号
buffers-barycentrics-perspective-correct = 重心坐标（透视校正）
buffers-barycentrics-affine = 重心坐标（仿射）
buffers-ambient-term = 环境光项
buffers-diffuse-term = 漫反射项
buffers-specular-term = 镜面反射项
buffers-normal = 法向量
buffers-texture-coordinates-u-v = 纹理坐标 (u, v)
buffers-mip-level = Mipmap 层级
buffers-texel-colour = 纹素颜色
buffers-texture-footprint = 纹理覆盖区域（足迹）
buffers-reflected-environment = 反射项（环境映射（反射映射））

## src/vocabulary/comparison.rs

comparison-flat-gouraud-phong = 平面 | Gouraud | Phong
comparison-affine-perspective-correct = 仿射 | 透视校正
comparison-1-4-msaa-4-ssaa = 1× | 4× MSAA | 4× SSAA
comparison-nearest-bilinear-trilinear-anisotropic = 最近邻 | 双线性 | 三线性 | 各向异性
comparison-trilinear-anisotropic-ripmap-summed-area = 三线性 | 各向异性 | ripmap | 求和面积表 | EWA
comparison-flat = 平面
comparison-affine = 仿射
comparison-perspective-correct = 透视校正
comparison-nearest = 最近邻
comparison-bilinear = 双线性
comparison-trilinear = 三线性
comparison-anisotropic-16 = 各向异性 16×
comparison-summed-area-table = 求和面积表

## src/vocabulary/explain.rs

explain-the-triangle-s-vertices-clip = 三角形的顶点：裁剪 → NDC → 屏幕
explain-inside-test-edge-functions = 内部测试：边函数
explain-interpolation-at-the-pixel-centre = 在像素中心插值
explain-texture-lookup = 纹理查询
explain-lighting = 光照
explain-the-colour = 颜色
explain-n-normal-l-to-the = n 法线 · l 指向光源 · v 指向视点


## src/vocabulary/names.rs

names-point-light = 点光源
names-spotlight = 聚光灯
names-directional-light = 平行光
names-ambient-light = 环境光

## src/vocabulary/profile.rs

profile-position-along-the-yellow-line = 沿黄线的位置（像素）
profile-intensity-rec-709-luminance = 亮度（Rec. 709）

## src/vocabulary/stage.rs

stage-model = 模型
stage-world = 世界
stage-view = 相机
stage-clip = 裁剪
stage-ndc = 规范化设备
stage-viewport = 视口
stage-rasterization = 光栅化
stage-depth = 深度
stage-shading = 着色
stage-texturing = 纹理
stage-output = 输出
stage-object-coordinates-the-mesh-as = 模型坐标系：物体建模时的坐标，p = (x, y, z, 1)。
stage-world-coordinates-m-p-with = 世界坐标系：M·p，M = T·Rz·Ry·Rx·S 把每个物体放入场景。
stage-eye-coordinates-v-m-p = 相机坐标系：V·M·p，V = LookAt(eye, at, up)；相机位于原点，朝向 −z。
stage-clip-coordinates-p-v-m = 裁剪坐标系：P·V·M·p（齐次坐标）。视见体内：−w ≤ x, y, z ≤ w。
stage-normalized-device-coordinates-x-y = 规范化设备坐标：(x, y, z)/w，规范立方体 [−1, 1]³。
stage-window-coordinates-x-w-x = 屏幕坐标：x_w = (x+1)·W/2，y_w = (y+1)·H/2，z_w = (z+1)/2。
stage-which-samples-each-triangle-covers = 每个三角形覆盖哪些采样点：边函数、左上规则、重心坐标。
stage-the-z-buffer-a-fragment = 深度缓冲（z-buffer）：片元比缓冲中的值更近时保留。
stage-lighting-i-k-a-i = 光照：I = k_a·I_a + f_att·(k_d·I_d·max(l·n, 0) + k_s·I_s·max(n·h, 0)^β)，按面、按顶点或按像素计算。
stage-texture-lookups-uv-interpolated-log = 纹理查询：插值得到 uv，λ = log₂(每像素纹素数) 选择 mipmap 层级；最近邻、双线性、三线性、各向异性。
stage-the-final-colour-each-pixel = 最终颜色：每个像素为其采样点的平均。

## src/export/handout.rs

handout-teacher-s-key-every-answer = 教师版：印出全部答案
handout-before-this-lesson = 先修课
handout-dash = ——
handout-stage = 阶段：
handout-the-animation-as-the-app = 动画，与应用中播放的相同
handout-the-animation-in-frames-from = 动画的分帧，从开始到结束：

## src/export/handout_exercise.rs

handout-exercise-your-answer = 你的答案（每项误差 { $tolerance } 以内）：
handout-exercise-question = 思考题：
handout-exercise-answer = 答案：
handout-exercise-show-the-answer = 显示答案
handout-exercise-the-debugger-at-pixel = 调试器：像素
handout-exercise-fragment = 片元
handout-exercise-triangle = 三角形
handout-exercise-discarded = 被丢弃
handout-exercise-exercise = 练习：

## src/vocabulary/explain.rs

explain-edge-opposite = 角点 { $edge } 对面的边
explain-sample-covered = 采样点 { $index } 被覆盖
explain-sample-not-covered = 采样点 { $index } 未被覆盖
explain-on-a-top-or-left-edge = 恰好在边 { $edge } 上，这是上边或左边：算作内部（左上填充规则）
explain-on-a-bottom-or-right-edge = 恰好在边 { $edge } 上，这是下边或右边：不算内部（左上填充规则）
explain-nearest-level = 最近的层级，最多为 { $max }
explain-trilinear = 三线性：按 t 混合第 k 层与第 k+1 层（λ 最多为 { $max }）
explain-four-texels = 读取的四个纹素，第 { $level } 层（{ $width }×{ $height }）
explain-directional-light = 平行光
explain-spot-light = 聚光灯
explain-point-light = 点光源
explain-light-towards = 光源 { $index }（{ $kind }）：指向它的单位向量
explain-mean-of-samples = 像素 { $samples } 个采样点的平均；其中 { $covered } 个属于该图元，其余保留各自的颜色或背景色
explain-behind-the-eye-no-ndc = 在视点之后：没有 NDC；裁剪先把三角形切开
explain-the-triangle-crosses-the-view = 三角形跨越视见体：该像素位于裁剪后多边形的一部分中
explain-the-corners-snapped = 三角形的角点，对齐到 1/256 像素，逆时针；v_k 是第 k 个顶点，c_k 是裁剪产生的角点
explain-the-pixel-centre = 像素中心
explain-depth-is-linear-in-screen = 深度在屏幕空间中是线性的
explain-perspective-correct-interpolation = 透视校正插值
explain-affine-interpolation-for-comparison = 仿射插值（用于对比）
explain-derivatives-as-a-gpu-takes = 导数按 GPU 的做法求：在像素所在的 2×2 像素块（quad）内作差，取在其左下像素 (x_q, y_q) 处；块内四个像素共用这组导数和 λ
explain-anisotropic-n-taps-along-the = 各向异性：沿覆盖区域（footprint）长轴取 N 个样本
explain-0-magnification-level-0 = λ ≤ 0：放大，使用第 0 层
explain-no-mipmap-level-0-always = 无 mipmap：总是第 0 层
explain-ripmap-level-i-halves-u = ripmap：第 i 层在 u 方向减半、第 j 层在 v 方向减半，各自由覆盖区域包围盒的一条边决定；斜向覆盖区域的包围盒偏大
explain-summed-area-table-the-exact = 求和面积表：覆盖区域包围盒内纹素的精确平均值，无论大小只需读表四次
explain-ewa-the-texels-inside-the = EWA：覆盖区域椭圆内的纹素按高斯权重平均，在椭圆短轴约为一个纹素的层级上进行
explain-nearest-the-texel-containing-the = 最近邻：包含该点的纹素
explain-the-mean-of-the-taps = 各样本的平均
explain-gouraud-lit-at-each-vertex = Gouraud：在每个顶点计算光照，再对颜色插值
explain-flat-lit-once-per-face = 平面着色：每个面在其引发顶点（最后一个顶点）处用面法线计算一次光照
explain-textured-the-texel-t-multiplies = 有纹理：纹素 T 乘以环境光项和漫反射项
explain-bump-or-normal-mapping-tilts = 凹凸映射或法线映射使法线倾斜
explain-a-mirror-it-reflects-its = 镜面：沿 r 反射环境，自身光照保留 1 − k
explain-the-material-k-a-k = 材质：k_a、k_d、k_s 与高光指数 p
explain-ambient-term = 环境光项
explain-distance-attenuation = 距离衰减
explain-the-spotlight-s-cone-half = 聚光灯的光锥，半角 θ
explain-diffuse-term-lambert = 漫反射项（Lambert）
explain-the-half-vector-between-l = l 与 v 之间的半程向量
explain-the-mirror-direction-of-l = l 的镜面反射方向
explain-specular-term-max-0-before = 镜面反射项；先取 max(·, 0) 再求幂，n·l ≤ 0 时为 0
explain-the-sum-of-the-terms = 各项之和
explain-the-colour-buffer-keeps-each = 颜色缓冲把每个采样点的颜色截断到 [0, 1] 再保存
explain-the-8-bit-colour-in = 图像中的 8 位颜色

## src/app/shortcuts.rs

shortcuts-next-step-of-a-lesson = 课程的下一步（无课程时为下一阶段）
shortcuts-previous-step-previous-stage = 上一步（上一阶段）
shortcuts-play-or-pause-the-step = 播放或暂停本步动画（重放过渡）
shortcuts-the-narration-card = 讲解卡片
shortcuts-the-parameters-panel = 参数面板
shortcuts-the-inspector-matrices-vertices-the = 检查器：矩阵、顶点、像素解释
shortcuts-the-matrix-card-over-the = 几何视图上的矩阵卡片
shortcuts-classroom-mode-large-type-the = 课堂模式：大字号，画面优先
shortcuts-the-shader-editor-glsl = 着色器编辑器（GLSL）
shortcuts-apply-the-shaders = 应用着色器
shortcuts-the-lesson-editor-record-what = 课程编辑器：把屏幕内容录制为步骤，撰写文字，调整顺序
shortcuts-the-lesson-editor-saves-its = 课程编辑器保存文件（要么完整写入，要么不写）
shortcuts-the-lesson-editor-redoes = 课程编辑器重做
shortcuts-the-lesson-editor-undoes = 课程编辑器撤销
shortcuts-shader-debugger-next-step-a = 着色器调试器：下一步（整个执行调用）
shortcuts-shader-debugger-one-step-back = 着色器调试器：后退一步
shortcuts-shader-debugger-next-step-into = 着色器调试器：下一步，进入调用
shortcuts-shader-debugger-out-of-this = 着色器调试器：跳出此函数
shortcuts-shader-debugger-run-to-the = 着色器调试器：运行到光标所在行
shortcuts-shader-debugger-on-to-the = 着色器调试器：继续到下一个断点
shortcuts-shader-debugger-back-to-the = 着色器调试器：倒退到上一个断点
shortcuts-shader-debugger-a-breakpoint-on = 着色器调试器：在光标所在行设置或取消断点；单击行号亦可
shortcuts-full-screen = 全屏
shortcuts-text-size = 字号
shortcuts-the-keyboard-to-the-picture = 键盘焦点移到画面，再移到旁边的画面，再回到步骤（Tab 键也能到达每个画面）
shortcuts-this-list = 本列表
shortcuts-wheel-drag = 滚轮、拖动
shortcuts-zoom-at-the-cursor-pan = 以光标为中心缩放、平移（几何视图：环绕）
shortcuts-click = 单击
shortcuts-select-a-pixel-or-a = 选择像素或顶点
shortcuts-in-the-picture-the-inspected = 画面中：移动所查看的像素（Shift：10 个像素）；几何视图或观察者视图环绕（Shift：10 倍）
shortcuts-in-the-picture-zoom = 画面中：缩放
shortcuts-in-a-geometry-view-the = 几何视图中：上一个或下一个顶点（Shift：跳 10 个）
shortcuts-the-keyboard-back-from-the = 键盘离开画面或着色器源码（源码中 Tab 用于缩进）：方向键重新用于换步

## src/app/views/debugger.rs

debugger-watch-not-run-yet = 监视 `{ $expression }`：到此步为止，此片元尚未执行第 { $line } 行
debugger-back = ← 后退
debugger-step-back = 后退一步
debugger-over = → 跳过
debugger-step-over-a-call-run = 单步跳过（整个执行调用）
debugger-into = ↓ 进入
debugger-step-into-a-call = 单步进入调用
debugger-out = ↑ 跳出
debugger-step-out-of-this-function = 单步跳出此函数
debugger-to-cursor = 到光标
debugger-run-to-the-cursor-s = 运行到光标所在行
debugger-breakpoint = ◀ 断点
debugger-back-to-the-previous-breakpoint = 倒退到上一个断点
debugger-breakpoint-2 = 断点 ▶
debugger-on-to-the-next-breakpoint = 继续到下一个断点

## src/spaces.rs

spaces-solid = 实线
spaces-dashed = 虚线
spaces-dotted = 点线
spaces-dash-dot = 点划线
spaces-dash-dot-dot = 双点划线
spaces-short-dashes = 短虚线
spaces-fate-drawn = 绘制
spaces-fate-clipped = 被裁剪
spaces-fate-outside = 在视见体外
spaces-fate-culled = 被剔除
spaces-fate-degenerate = 退化
spaces-fate-not-finite = 非有限值（NaN 或 ∞）
spaces-fate-and-line = { $fate }：{ $line }

## src/vocabulary/alt_text.rs (with variables)

alt-text-buffer = { $name }缓冲
alt-text-size = ，{ $w }×{ $h } 像素
alt-text-beside = （另有：{ $others }）
alt-text-at-pixel = {" "}在像素 ({ $x }, { $y }) 处，{ $object }的三角形 { $triangle }
alt-text-stage = { $stage }阶段
watch-picture-after-vertex-line = 顶点着色器第 { $line } 行之后，经插值
depth-and-mips-curve-alt = 深度曲线：窗口深度 z_w 随视点距离 d 变化，近 { $near }，远 { $far }

## src/lab/words.rs: a lab's verdict

lab-words-passed = 通过：全部 { $total } 个像素与 pipelens 自带的一致（每个通道相差不超过 { $tolerance }/255）。
lab-words-colours-differ = 颜色最多相差 { $largest }/255
lab-words-covered-differently = { $n } 个覆盖不同
lab-words-at-another-depth = { $n } 个深度不同
lab-words-another-triangle = { $n } 个属于另一个三角形
lab-words-clause-separator = ；
lab-words-not-yet = 还没有通过：{ $total } 个像素中 { $matching } 个一致，{ $differ } 个不同（{ $how }）。从上往下读，第一个是 { $first }。
lab-words-at-the-pixel = 在所检查的像素 { $pixel } 处，你的 `{ $name }`（第 { $line } 行）是 { $yours }；pipelens 自带的着色器得到 { $theirs }。
lab-words-at-the-vertex = 在顶点 { $row }（第一个错误像素所在三角形的一个角）处，你的顶点着色器中的 `{ $name }`（第 { $line } 行）是 { $yours }；pipelens 自带的得到 { $theirs }。
lab-words-not-normalized = 你的长度是 { $length }，pipelens 的是 1：它归一化了吗？
lab-words-first-vertex = 第一个出错的顶点在第 { $row } 行：你的裁剪坐标 { $yours }，pipelens 的 { $theirs }。
lab-words-matrix-entry = 第 { $row } 行第 { $column } 列是 { $yours }（{ $matrix } 中为 { $theirs }）
lab-words-matrix-more = ；还有 { $more } 个
lab-words-matrix = 你的 `{ $name }`（第 { $line } 行）与 pipelens 的 { $matrix } 有 { $n } 个元素不同：{ $entries }{ $more }。
lab-words-curve = 曲线
lab-words-surface = 曲面
lab-words-curve-passed = 通过：你的{ $what }的全部 { $total } 个点与 pipelens 的 { $b } 相差都不超过 { $tolerance }。
lab-words-curve-first = 第一个在 { $at }：你的 { $yours }，pipelens 的 { $theirs }。
lab-words-curve-not-yet = 还没有通过：{ $total } 个{ $what }点中 { $matching } 个与 pipelens 的 { $b } 相差不超过 { $tolerance }（最远相差 { $largest }）。{ $first }

## src/vocabulary/names.rs: the built-in names of figures' parts and usual objects (looked up as part-NAME)

part-robot-arm = 机械臂
part-humanoid = 人形
part-base = 支架
part-lower-arm = 下臂
part-upper-arm = 上臂
part-torso = 躯干
part-head = 头
part-left-arm-upper = 左上臂
part-left-arm-lower = 左前臂
part-right-arm-upper = 右上臂
part-right-arm-lower = 右前臂
part-left-leg-upper = 左大腿
part-left-leg-lower = 左小腿
part-right-leg-upper = 右大腿
part-right-leg-lower = 右小腿
part-floor = 地面
part-cube = 立方体
part-sphere = 球
part-wall = 墙
part-triangle = 三角形
part-two-triangles = 两个三角形
part-torus = 圆环
part-quad = 四边形
part-curve = 曲线
part-mirror = 镜面
part-body = 身体
part-arm = 机械臂
part-lower = 下臂
part-upper = 上臂
part-left-upper-arm = 左上臂
part-left-lower-arm = 左前臂
part-right-upper-arm = 右上臂
part-right-lower-arm = 右前臂
part-left-upper-leg = 左大腿
part-left-lower-leg = 左小腿
part-right-upper-leg = 右大腿
part-right-lower-leg = 右小腿
names-shadow-of = { $object }的影子

## src/lesson/param/describe.rs: a parameter's words (looked up as param-KEY), as the panel says them

param-camera = 相机
param-projection = 投影
param-render = 渲染
param-lights = 光源
param-shadow = 阴影
param-eye = 视点
param-at = 参考点
param-up = 上方向
param-near = 近平面 near
param-far = 远平面 far
param-translate = 平移
param-rotate = 旋转
param-scale = 缩放
param-color = 颜色
param-axis = 旋转轴
param-axis-angle = 绕轴旋转角
param-slerp-axis = slerp 终点旋转轴
param-slerp-angle = slerp 终点旋转角
param-slerp-t = slerp 参数 t
param-position = 位置
param-direction = 方向
param-intensity = 强度
param-cutoff = 截止角
param-exponent = 衰减指数
param-light = 光源
param-shininess = 高光指数 p
param-normals = 法线
param-lod-bias = mip 偏移
param-max-steps = 循环步数上限
param-samples = 采样数
param-anisotropy = 各向异性
param-uniforms = 着色器的 uniform
describe-of = { $whole }的{ $part }
describe-of-latin = { $whole }的 { $part }
describe-light-part = { $light } 的{ $part }
describe-group-part = { $group }的{ $part }
describe-group-part-latin = { $group }的 { $part }

## src/lab/quantity.rs

quantity-uv-differs = 在所检查的像素 { $pixel } 处，你的 `{ $name }`（第 { $line } 行）是 { $yours }；pipelens 在此处经透视校正插值的 uv 是 { $theirs }。
quantity-lod-differs = 在所检查的像素 { $pixel } 处，你的 `{ $name }`（第 { $line } 行）给出 λ = { $yours }；pipelens 在此处的 λ 是 { $theirs }：像素每走一步，覆盖区域是 L = 2^λ = { $footprint } 个纹素（uv { $uv }）。
quantity-texel-differs = 在所检查的像素 { $pixel } 处，你的 `{ $name }`（第 { $line } 行）给出 { $yours }；pipelens 的过滤在此处读出 { $theirs }（uv { $uv }）。
quantity-the-texture = { " " }{ $w } × { $h } 的纹理
quantity-the-level = 第 { $k } 层（{ $w } × { $h }）
quantity-bilinear-differs = 在所检查的像素 { $pixel } 处，你的 `{ $name }`（第 { $line } 行）给出 { $yours }；pipelens 的双线性过滤在此处读出 { $theirs }：uv { $uv } 在{ $on }上是 (x, y) = ({ $x }, { $y })（x = u·w − ½，y = v·h − ½），位于纹素 ({ $i }, { $j }) 与 ({ $i1 }, { $j1 }) 之间，按 s = { $s }、t = { $t } 混合。

## src/lesson/answer.rs

answer-tolerance-and-relative = ±{ $t }；小于 { $below } 的项在其自身的 5% 以内
answer-your-value = 你的数值
answer-named-entry = { $name } 分量
answer-component = 第 { $n } 个分量
answer-row-column = 第 { $row } 行第 { $column } 列
answer-list-separator = ；
answer-right = 正确：每一项都在 { $tolerance } 之内。
answer-still-empty = 尚未填写：{ $cells }。
answer-not-a-number = { $cell }：“{ $text }”不是数值（{ $why }）。
answer-too-large = { $cell } = { $typed } 大了 { $by }
answer-too-small = { $cell } = { $typed } 小了 { $by }
answer-not-yet = 还不对（{ $entries } 项中有 { $off } 项超出 { $tolerance }）：{ $each }。

## src/lab/submission.rs

submission-not-a-lab = { $lesson } 的第 { $step } 步不是练习
submission-file-does-not-compile = 无法编译：{ $file }.glsl，{ $first }
submission-its-run-stopped = 可以编译，但运行中止：{ $why }
submission-does-not-compile = 无法编译：{ $first }{ $more ->
        [0] {""}
       *[other] （另有 { $more } 条消息）
    }

## src/vocabulary/compile.rs

compile-cannot-stand-here = 这里不能出现 `{ $found }`
compile-file-ends-where = 文件在应当出现 { $expected } 的地方结束了
compile-should-come-first = 这里不能出现 `{ $found }`：应当先有 { $expected }
compile-or = 或
compile-token-a-name = 一个名字
compile-token-a-type = 一个类型
compile-token-a-whole-number = 一个整数
compile-token-a-number = 一个数
compile-token-true-or-false = true 或 false
compile-token-the-end-of-the-file = 文件结尾
compile-missing-semicolon = 这一行末尾缺少 `;`
compile-unexpected-end = 文件提前结束了：缺少 `{ "}" }` 或 `)`
compile-unknown-variable = `{ $n }` 在这里没有声明：请在第一次使用前声明它，或检查拼写
compile-unknown-type = `{ $n }` 不是 GLSL 的类型（float、vec2、vec3、vec4、int、bool、mat3、mat4……）
compile-no-such-field = 这个值没有这样的成员或分量
compile-no-field-named = 这个值没有成员或分量 `{ $n }`（vec3 有 x、y、z；vec2 没有 z）
compile-no-function-matches = 没有与这次调用匹配的函数：请检查函数名和参数的类型
compile-no-function-named = 没有接受这些参数的函数 `{ $n }`：请检查函数名、参数的个数和类型，以及它是否在这一行之前声明
compile-already-declared = `{ $n }` 在这里声明了两次：给第二个换个名字，或去掉类型直接给第一个赋值
compile-function-already-defined = 这个函数定义了两次
compile-cannot-combine = 这个运算符两边的类型不能一起运算：vec3 与 vec4 需要 v.xyz 或 vec4(v, 1.0)；int 与 float 需要 float(i)，或把 1 写成 1.0
compile-too-many-arguments = 这个构造函数给的数比它的类型能容纳的多（vec3 取 3 个，mat4 取 16 个）
compile-bad-constructor = 不能用这些参数构造这个类型
compile-not-constant = 这里必须在编译时就确定：一个数，或由数构成的 `const`
compile-not-assignable = 不能给它赋值：`uniform`、`in` 输入和 `const` 都是只读的——先把它复制到一个局部变量
compile-void-value = `void` 函数不返回值，所以这里没有可用的值
compile-version-not-first = `#version` 必须是着色器的第一行
compile-invalid-version = GLSL 没有版本 `{ $v }`：请写 `#version 330 core`（旧版 GLSL 写 110 或 120）
compile-float-modulo = GLSL 的 `%` 只能用于整数（int、uint、ivec……）：浮点数请写 mod(a, b)
compile-bad-swizzle = 这个分量选择（swizzle）不允许：在 `=` 左边每个分量只能出现一次（v.xy，而不是 v.xx），最多四个
compile-type-mismatch = 值的类型与变量的类型不同：vec3 放进 vec4 需要构造 vec4(v, 1.0)；vec4 放进 vec3 需要选取 v.xyz；int 变成 float 需要 float(i)
compile-return-type = 这个函数返回的值不是它声明的类型，或者它可能没有 `return` 就结束了
compile-integer-overflow = 这个整数超出了 32 位的范围
compile-not-implemented = pipelens 还不能运行这种 GLSL 写法（{ $what }）
compile-not-run-yet = pipelens 还不能运行 `{ $name }`
compile-sampler-parameter = pipelens 只能把 `sampler2D` 或 `samplerCube` 传给函数：它不绑定 `{ $ty }` 类型的纹理
compile-recursion = GLSL 不允许递归：`{ $name }` 调用了它自己
compile-defined-below = `{ $name }` 在定义之前就被调用了：把它的定义移到上面，或在上面先声明它（写出它的第一行并以 `;` 结尾）
compile-argument-types = 实参与 `{ $name }` 的形参 { $parameters } 不相符：请检查每个实参的类型
compile-at = 第 { $line } 行第 { $column } 列：{ $said }
compile-vertex-shader = 顶点着色器
compile-fragment-shader = 片元着色器
compile-stage-message = { $stage }，{ $message }
compile-file-message = { $file }.glsl，{ $message }
compile-endless-loop = 循环执行超过了 { $budget } 步（是不是死循环？如果它本来就要运行更久，请在 [scene.render] 中用 `max_steps` 提高上限）
compile-index-out-of-range-of = 下标 { $index } 越界：`{ $name }` 的下标只能是 0 到 { $last }
compile-index-out-of-range = 下标 { $index } 越界（只能是 0 到 { $last }）
compile-texel-outside = texelFetch 读取的 ({ $i }, { $j })（第 { $level } 层）在纹理之外
compile-division-by-zero = 整数除以零
compile-remainder-by-zero = 整数对零取余（%）
compile-did-you-mean = （是不是想写 `{ $name }`？）
compile-unknown-uniform = pipelens 不设置名为 `{ $name }` 的 uniform{ $meant }；它设置的 uniform：{ $uniforms }。自己的 uniform 可以是 float、int、bool、vec2、vec3 或 vec4，在其后的注释中写明控件：`// 0..4 = 1.5`
compile-own-uniform-control = `{ $name }` 是你自己的 uniform；它的注释看起来像控件（`// 最小..最大 = 初值`），但写得不对：范围须是 最小..最大（最小小于最大），初值的个数须与类型相符
compile-uniform-type = pipelens 的 `{ $name }` 是 { $expected }，这里却声明为 { $written }
compile-texture-type = pipelens 把 `{ $name }` 绑定为 { $expected }，这里却声明为 { $written }
compile-unknown-texture = pipelens 不绑定名为 `{ $name }` 的纹理{ $meant }；物体的纹理是 `uniform sampler2D tex;`，凹凸或法线贴图是 `uniform sampler2D detail;`，它所反射的立方体贴图是 `uniform samplerCube environment;`
compile-unknown-attribute = pipelens 不提供名为 `{ $name }` 的顶点属性{ $meant }；它提供的属性：{ $attributes }
compile-one-colour-output = pipelens 只画到一个颜色缓冲：只为片元的颜色声明一个 `out vec4`
compile-uniform-written = `{ $name }` 是 uniform：着色器只能读它，不能给它赋值
compile-no-position = 顶点着色器从未写 `gl_Position`（裁剪空间位置）：请加上 `gl_Position = mvp * vec4(position, 1.0);`
compile-no-output = 片元着色器没有输出：请声明 `out vec4 color;`，并把片元的颜色写进去
compile-output-not-written = 片元着色器从未写 `{ $name }`：这个片元将没有颜色
compile-varying-components = `{ $name }` 在这里有 { $here } 个分量，在顶点着色器中却有 { $vertex } 个：请在两边用相同的类型声明它
compile-no-varying-source = 顶点着色器没有可插值到这个输入的输出 `{ $name }`；它的输出：{ $outputs }
compile-no-outputs = 无
compile-hook-signature = { $calls }：请严格按这个签名定义它（不要 `main`，也不要自己的输入或输出）
compile-hook-calls-inside = 光栅化器对每个采样调用 `{ $signature }`
compile-hook-calls-depth-test = 光栅化器对三角形覆盖的每个采样调用 `{ $signature }`
compile-hook-calls-curve = 画贝塞尔曲线时，pipelens 对曲线上的每个点调用 `{ $signature }`
compile-hook-calls-shadow-matrix = 画阴影时，pipelens 每帧为平面 y = 0 调用一次 `{ $signature }`
compile-hook-calls-patch = 画贝塞尔曲面时，pipelens 对曲面网格的每个顶点调用 `{ $signature }`

## src/vocabulary/run.rs

run-cannot-draw = 无法绘制场景：{ $why }
run-problem-separator = ；
run-shadow-matrix = shadow_matrix(vec3({ $x }, { $y }, { $z })) 返回的矩阵含有非有限的数（是否除以了零？）：{ $matrix }
run-code = 物体 { $object } 的{ $part }，{ $message }
run-code-in-file = 物体 { $object } 的{ $part }，{ $file }，{ $message }
run-part-inside = 函数 inside
run-part-depth-test = 函数 depth_test
run-part-curve = 函数 de_casteljau
run-part-shadow-matrix = 函数 shadow_matrix
run-part-patch = 函数 bezier_patch
run-camera-not-finite = 相机的 eye、at 和 up 必须是有限的数
run-eye-at-coincide = 视点与参考点重合（{ $at }）：没有观察方向
run-up-parallel = 上方向 { $up } 与观察方向 { $dir } 平行：u = v_up × n 为零，相机坐标系无法确定（请换一个上方向）
run-zero-axis = 旋转轴是零向量
run-object-transform = 物体 `{ $name }`：它的变换必须是有限的数
run-object-colour = 物体 `{ $name }`：它的颜色必须是有限的数
run-viewport-width = 视口的宽度必须在 1 到 { $max } 像素之间，现在是 { $got }
run-viewport-height = 视口的高度必须在 1 到 { $max } 像素之间，现在是 { $got }
run-capture-too-large = { $width }×{ $height } 像素 × { $samples } 个采样的捕获约需 { $megabytes } MB，超过了允许的 { $allowed } MB；请减小尺寸或采样数
run-background = 背景颜色必须是有限的数
run-fovy = fovy 必须在 0° 到 180° 之间（不含两端），现在是 { $fovy }
run-aspect = aspect 必须是正数，现在是 { $aspect }
run-left-right = left 必须小于 right，现在 left = { $left }，right = { $right }
run-bottom-top = bottom 必须小于 top，现在 bottom = { $bottom }，top = { $top }
run-near = 透视投影的 near 必须为正（它是视点前方的距离），现在是 { $near }
run-far-near = far 必须大于 near，现在 near = { $near }，far = { $far }
run-projection-not-finite = 投影的每个参数都必须是有限的数

## src/lab/samples.rs

samples-inside = 在内部
samples-outside = 在外部
samples-writes-the-fragment = 写入这个片元
samples-keeps-what-is-stored = 保留已存的值
samples-on-a-top-or-left-edge = （恰在边上：上边或左边）
samples-on-neither-top-nor-left = （恰在边上：既非上边也非左边）
samples-edge-value = E{ $edge } = { $value }{ $on }
samples-inside-differs = 在像素 ({ $x }, { $y })，采样点 ({ $sx }, { $sy }) 对三角形 { $triangle }：{ $edges }。pipelens：{ $theirs }；你的 inside()：{ $yours }。
samples-depth-differs = 在像素 ({ $x }, { $y }) 的第 { $sample } 个采样点：三角形 { $triangle } 的片元 z = { $z }，深度缓冲中已存 { $stored }。pipelens { $theirs }；你的 depth_test(z, stored) { $yours }。

## src/lesson/forbid.rs

forbid-own-uniform = 还没有通过：{ $file } 第 { $line } 行声明了 pipelens 自带的 `{ $name }`——本练习要求你自己算出它，这里不能使用这个 uniform。
forbid-own-function = 还没有通过：{ $file } 第 { $line } 行调用了 `{ $name }()`——本练习要求你自己算出它的结果，这里不能调用它。

## src/lesson/typed.rs

typed-unexpected = 不应出现 `{ $what }`
typed-unclosed = 有一个 `(` 没有闭合
typed-missing-at-end = 末尾缺少一个数
typed-not-a-number = `{ $what }` 不是数
typed-unknown-name = pipelens 不认识函数 `{ $what }`：可用 sqrt、sin、cos、tan、cot、asin、acos、atan、ln、log2、log10、exp、deg、pi
typed-not-finite = 不是有限的数
typed-several = 一个格子里有多个数：请每格填一个数

## src/vocabulary/formulas.rs

formula-frustum-l-r-b-t-near = Frustum(l, r, b, t, near, far)：先错切，再缩放，最后透视规范化
formula-frustum-right-right-top-top-near = Frustum(−right, right, −top, top, near, far)，其中 top = near·tan(fovy/2)，right = top·aspect
formula-m-t-r-n-rz-ry = M = T·R(n, θ)·Rz·Ry·Rx·S：先缩放，再绕 x、y、z 旋转，然后绕轴 n 旋转，最后平移
formula-m-t-r-slerp-q-q = M = T·R(slerp(q₀, q₁, t))·Rz·Ry·Rx·S：先缩放，再绕 x、y、z 旋转，然后转到两个朝向之间的某处，最后平移
formula-the-rotation-part-way-from-the = 沿较短的大圆弧，从第一个朝向转到第二个朝向途中的旋转
formula-m-t-rz-ry-rx-s = M = T·Rz·Ry·Rx·S：先缩放，再绕 x、y、z 旋转，最后平移
formula-m-parent-t-rz-ry-rx = M = parent·T·Rz·Ry·Rx·S：先是物体自身的变换，再是父节点的变换
formula-m-m-local-the-parent-s = M ← M·local：父节点的组合矩阵乘以本部件的放置矩阵
formula-t-0-h-0-t-l = T(0, h+ε, 0)·[T(l)·M_p·T(−l)]·T(0, −h, 0)：从光源投影到平面 y = h
formula-t-joint-on-the-torso-rx = T(躯干上的关节)·Rx(θ)
formula-l-r-b-t-f-n = [l,r]×[b,t]×[f,n] → [−1,1]³：先把中心平移到原点，再缩放
formula-back-up-to-the-plane-lifted = 移回平面，并抬高 ε
formula-your-shadow-matrix-l = 你的 shadow_matrix(l)
formula-centre-the-view-volume-at-the = 把视见体的中心移到原点，再缩放为立方体 [−1,1]³
formula-move-the-light-back-to-xl = 把光源移回 (xl, yl, zl)
formula-move-the-light-to-the-origin = 把光源移到原点
formula-perspective-normalization-far-near-far-near = 透视规范化：α = −(far+near)/(far−near)，β = −2·far·near/(far−near)
formula-perspective-projection-onto-y-yl = 透视投影到平面 y = −yl
formula-project-from-the-light-onto-the = 从光源投影到平面 y = 0
formula-rotation-about-an-arbitrary-axis-by = 绕任意轴旋转：先把轴对齐到 z 轴
formula-rows-u-v-n-and-p = 行为 u、v、n，最后一列为 −p·u、−p·v、−p·n，其中 n = (eye−at)/|eye−at|，u = v_up×n/|v_up×n|，v = n×u；等于 GAMES101 的 R_view·T_view（g = at − eye，t = up）
formula-rows-g-t-t-g = 各行：g×t、t、−g
formula-shear-h-cot-l-r-2 = 错切 H(θ, φ)：cot θ = (l+r)/(2·near)，cot φ = (t+b)/(2·near)
formula-squish-the-frustum-into-a-box = 先把视锥挤压成长方体（n 和 f 不变），再做正交投影
formula-the-joint = 关节
formula-the-part-s-composite-times-its = 部件的组合矩阵乘以其实例矩阵
formula-the-plane-to-y-0 = 把平面移到 y = 0
formula-the-rotation-itself-about-z = 旋转本身：绕 z 轴
formula-to-the-joint = 移到关节
formula-undo-the-turn-into-the-xz = 撤销转入 xz 平面的旋转
formula-undo-the-turn-onto-z = 撤销转到 z 轴的旋转
formula-where-the-figure-stands = 人物所站的位置
formula-x-n-x-z-y-n = x' = n·x/z，y' = n·y/z；近平面和远平面的 z 保持不变
formula-x-w-x-1-width-2 = x_w = (x+1)·width/2，y_w = (y+1)·height/2，z_w = (z+1)/2

## src/vocabulary/glsl.rs

glsl-pipelens-per-pixel-phong-frequency-lighting = pipelens 的逐像素（Phong 频率）光照，用 Blinn-Phong 模型，写成着色器：
glsl-l-k-a-c-i-a = L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(n·h, 0)^p)
glsl-with-h-normalize-l-v-f = 其中 h = normalize(l + v)，f_att = 1/(a + b·d + c·d²)，在光锥内 f_spot = (cos φ)^e。
glsl-pipelens-declares-these-before-your-code = pipelens 在你的代码之前声明了这些（你自己的程序要自己声明）：
glsl-the-surface-colour = 表面颜色
glsl-pipelens-flat-shading-the-fragment-half = pipelens 的平面着色，片元部分：每个面一个法向量，每个面一次光照。
glsl-the-face-normal-is-the-cross = 面法向量是面所在平面内两个方向的叉积：当 x 和 y
glsl-on-the-screen-the-world-position = 在屏幕上移动时，世界坐标 p 在面内移动，所以 ∂p/∂x 和 ∂p/∂y 就是两个这样的
glsl-directions-and-n-face-normalize-dfdx = 方向，n_face = ±normalize(dFdx(p) × dFdy(p))，正面取 +。（一般只有
glsl-direction-holds-in-general-p1-p0 = 方向成立：(p1 − p0)×(p2 − p0) = 2·面积·(∂p/∂x × ∂p/∂y) 只对仿射
glsl-mapping-alone-not-under-perspective = 映射成立，透视下不成立。）
glsl-the-blinn-phong-lighting-is-that = Blinn-Phong 光照与 gouraud.vert 的相同，在引发顶点 f_pos 处计算：
glsl-fragment-of-the-face-computes-the = 面上每个片元算出同一个颜色。有纹理的表面按白色照亮（c = 1），
glsl-its-texel-modulates-ambient-and-diffuse = 纹素再调制环境光和漫反射，与 Gouraud 着色相同。
glsl-pipelens-flat-shading-the-vertex-half = pipelens 的平面着色，顶点部分：pipelens.vert 的顶点阶段，以及一个面
glsl-face-is-lit-with-opengl-gives = 光照所用的值。OpenGL 让 `flat` 输出在整个三角形上取引发顶点（最后一个顶点）的值：
glsl-whole-triangle-the-face-is-lit = 面在这个顶点处、用它的颜色照亮。
glsl-displacement-mapping-s-height-map-none = 位移贴图的高度图（没有时为黑色）
glsl-its-k-0-without-one = 它的 k（没有位移贴图时为 0）
glsl-world-position-interpolated-its-derivatives-give = 插值后的世界坐标：它的导数给出面法向量
glsl-the-provoking-vertex-s-world-position = 引发顶点的世界坐标
glsl-and-its-colour = 以及它的颜色
glsl-displacement-mapping-moves-the-vertex-along = 位移贴图沿法向量移动顶点：p' = p + k·h(u, v)·n，h 为
glsl-height-map-s-luminance-bilinear-level = 高度图的亮度（双线性，第 0 层）。
glsl-pipelens-gouraud-shading-the-fragment-half = pipelens 的 Gouraud 着色，片元部分：三个顶点的光照经插值
glsl-interpolated-a-texel-modulates-the-ambient = 到达这里；纹素调制环境光和漫反射部分（OpenGL 的 GL_MODULATE），
glsl-specular-part-is-added-on-top = 高光部分再加在上面。
glsl-ambient-diffuse-lit-with-a-white = 环境光 + 漫反射，有纹理时按白色表面计算
glsl-pipelens-gouraud-shading-the-vertex-half = pipelens 的 Gouraud 着色，顶点部分：每个顶点的 Blinn-Phong 光照，每个顶点
glsl-vertex-with-its-own-normal = 计算一次，用它自己的法向量，
glsl-l-k-a-c-i-a-2 = L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(n·h, 0)^p)，
glsl-sent-to-the-fragment-stage-to = 送到片元阶段，在三角形上插值（gouraud.frag）。有纹理的
glsl-surface-is-lit-white-here-c = 表面在这里按白色照亮（c = 1）；纹素在每个像素上调制环境光和漫反射。
glsl-ambient-diffuse = 环境光 + 漫反射
glsl-specular = 高光
glsl-pipelens-per-pixel-blinn-phong-lighting = pipelens 带凹凸贴图或法线贴图的逐像素 Blinn-Phong 光照（blinn_phong.frag）：
glsl-interpolated-normal-n-is-tilted-in = 插值得到的法向量 n 先在切线坐标系中倾斜，再计算光照。
glsl-tangent-frame-t-p-u-b = 切线坐标系：T = ∂p/∂u，B = ∂p/∂v。p 和 uv 的屏幕导数满足
glsl-dfdx-p-t-dfdx-u-b = dFdx(p) = T·dFdx(u) + B·dFdx(v)，dFdy(p) = T·dFdy(u) + B·dFdy(v)，
glsl-two-equations-solved-for-t-and = 解这两个方程得到 T 和 B（与由三角形的边求出的 T、B 相同）。
glsl-t-normalize-t-n-n-t = T' = normalize(T − n(n·T))，B' = ±n×T'（B 的符号），n' = normalize(T'·x + B'·y + n·z)：
glsl-bump-map-games101-x-y-z = 凹凸贴图（GAMES101）：(x, y, z) = (−dU, −dV, 1)，dU = k_h·k_n·(h(u + 1/w, v) − h(u, v))，
glsl-dv-k-h-k-n-h = dV = k_h·k_n·(h(u, v + 1/h) − h(u, v))，h 为纹素的亮度；
glsl-normal-map-x-y-z-2 = 法线贴图：          (x, y, z) = 2·texel − 1。
glsl-0-none-1-bump-map-2 = 0 无，1 凹凸贴图，2 法线贴图
glsl-k-h-k-n = k_h·k_n
glsl-pipelens-per-pixel-blinn-phong-lighting-2 = pipelens 对镜面物体的逐像素 Blinn-Phong 光照（环境映射），写成着色器：
glsl-l-1-k-ambient-diffuse-specular = L = (1 − k)·(环境光 + 漫反射) + 高光 + k·env(r)，   r = 2(n·v)n − v = reflect(−v, n)
glsl-with-ambient-k-a-c-i = 其中 环境光 = Σ k_a·c·I_a，漫反射 = Σ f_att·f_spot·k_d·c·I·max(n·l, 0)，
glsl-specular-f-att-f-spot-k = 高光 = Σ f_att·f_spot·k_s·I·max(n·h, 0)^p，env(r) 是沿方向 r 看到的立方体贴图，
glsl-k-the-reflectivity-a-mirror-shows = k 是反射率：镜面显示所反射内容的 k 倍，并保留自身光照的 1 − k 倍。
glsl-the-surroundings-x-x-y-y = 周围环境：+x、−x、+y、−y、+z、−z 六个面
glsl-k = k
glsl-the-mirror-direction-2-n-v = 镜面反射方向 2(n·v)n − v
glsl-env-r = env(r)
glsl-the-height-or-normal-map-bilinear = 高度图或法线贴图：双线性、重复、第 0 层
glsl-the-luminance-of-the-height-map = 高度图在 uv 处的亮度：h(u, v)。
glsl-n-tilted-by-the-bump-or = 在 uv 处按凹凸贴图或法线贴图倾斜后的 n。
glsl-the-uvs-do-not-grow-across = uv 在这个三角形上不变化：没有切线坐标系
glsl-pipelens-per-pixel-phong-frequency-lighting-2 = pipelens 的逐像素（Phong 频率）光照，用 Phong 反射模型，写成着色器：
glsl-l-k-a-c-i-a-3 = L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(r·v, 0)^p)
glsl-with-r-reflect-l-n-2 = 其中 r = reflect(−l, n) = 2(n·l)n − l，f_att = 1/(a + b·d + c·d²)，在光锥内
glsl-the-cone-blinn-phong-frag-differs = f_spot = (cos φ)^e。blinn_phong.frag 只有一行不同：用 n·h 代替 r·v。
glsl-pipelens-own-vertex-stage-as-a = pipelens 自带的顶点阶段，写成着色器：位置（有位移贴图时先位移）
glsl-through-m-v-and-p-one = 依次经过 M、V、P 三个矩阵（模型 → 世界 → 眼睛 → 裁剪，与顶点表
glsl-table-shows-them-and-what-the = 显示的顺序相同），以及片元阶段要插值的量（世界坐标、单位世界法向量、纹理坐标、颜色）。
glsl-world-position-m-p = 世界坐标 M·p
glsl-world-normal-m-t-n-normalized = 世界法向量 (M⁻¹)^T·n，已归一化（插值会再次使它变短）
glsl-pipelens-unlit-shading-as-a-shader = pipelens 的无光照着色，写成着色器：表面颜色原样输出，物体有纹理时
glsl-is-textured-else-the-vertex-colour = 用纹素，否则用（插值后的）顶点颜色。

## src/vocabulary/trace.rs

trace-if-true = if：条件成立 → then
trace-if-false = if：条件不成立 → else
trace-iteration = 循环：第 { $k } 次迭代
trace-loop-holds = 循环条件：成立 → 再迭代一次
trace-loop-ends = 循环条件：不成立 → 循环结束
trace-break = break：跳出循环
trace-continue = continue：进入下一次迭代
trace-call = 调用 { $name }()
trace-returns = { $name }() 返回 { $value }
trace-return-from = 从 { $name }() 返回
trace-discard = discard：丢弃这个片元

## src/app/views/shader_source.rs

shader-source-gutter = 行号 1 到 { $lines }（单击行号设置或清除断点）
shader-source-gutter-breakpoints = ；断点在第 { $lines } 行
shader-source-gutter-current = ；调试器在第 { $line } 行
shader-source-gutter-messages = ；第 { $lines } 行有消息
