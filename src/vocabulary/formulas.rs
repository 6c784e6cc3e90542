//! The formulas of the matrices in Chinese. The core names each matrix with a formula in English
//! words (the pipeline crate has no language); these are their Chinese versions, in the notes'
//! terms. Formulas that are only mathematics read the same in both languages and are not listed.

use super::Lang;

const FORMULAS_ZH: &[(&str, &str)] = &[
    (
        "Frustum(l, r, b, t, near, far): shear, scale, then perspective normalization",
        "Frustum(l, r, b, t, near, far)：先错切，再缩放，最后透视规范化",
    ),
    (
        "Frustum(−right, right, −top, top, near, far) with top = near·tan(fovy/2), right = top·aspect",
        "Frustum(−right, right, −top, top, near, far)，其中 top = near·tan(fovy/2)，right = top·aspect",
    ),
    (
        "M = T·R(n, θ)·Rz·Ry·Rx·S: scale, rotate about x, y, z, then about the axis n, then translate",
        "M = T·R(n, θ)·Rz·Ry·Rx·S：先缩放，再绕 x、y、z 旋转，然后绕轴 n 旋转，最后平移",
    ),
    (
        "M = T·R(slerp(q₀, q₁, t))·Rz·Ry·Rx·S: scale, rotate about x, y, z, then part way between two orientations, then translate",
        "M = T·R(slerp(q₀, q₁, t))·Rz·Ry·Rx·S：先缩放，再绕 x、y、z 旋转，然后转到两个朝向之间的某处，最后平移",
    ),
    (
        "the rotation part way from the first orientation to the second, along the shorter arc",
        "沿较短的大圆弧，从第一个朝向转到第二个朝向途中的旋转",
    ),
    (
        "M = T·Rz·Ry·Rx·S: scale, rotate about x, y, z, then translate",
        "M = T·Rz·Ry·Rx·S：先缩放，再绕 x、y、z 旋转，最后平移",
    ),
    (
        "M = parent·T·Rz·Ry·Rx·S: the object's own transform, then its parent's",
        "M = parent·T·Rz·Ry·Rx·S：先是物体自身的变换，再是父节点的变换",
    ),
    (
        "M ← M·local: the parent's composite times this part's placement",
        "M ← M·local：父节点的组合矩阵乘以本部件的放置矩阵",
    ),
    (
        "T(0, h+ε, 0)·[T(l)·M_p·T(−l)]·T(0, −h, 0): project from the light onto y = h",
        "T(0, h+ε, 0)·[T(l)·M_p·T(−l)]·T(0, −h, 0)：从光源投影到平面 y = h",
    ),
    ("T(joint on the torso)·Rx(θ)", "T(躯干上的关节)·Rx(θ)"),
    (
        "[l,r]×[b,t]×[f,n] → [−1,1]³: translate the centre to the origin, then scale",
        "[l,r]×[b,t]×[f,n] → [−1,1]³：先把中心平移到原点，再缩放",
    ),
    ("back up to the plane, lifted by ε", "移回平面，并抬高 ε"),
    ("your shadow_matrix(l)", "你的 shadow_matrix(l)"),
    (
        "centre the view volume at the origin, then scale it to the cube [−1,1]³",
        "把视见体的中心移到原点，再缩放为立方体 [−1,1]³",
    ),
    (
        "move the light back to (xl, yl, zl)",
        "把光源移回 (xl, yl, zl)",
    ),
    ("move the light to the origin", "把光源移到原点"),
    (
        "perspective normalization: α = −(far+near)/(far−near), β = −2·far·near/(far−near)",
        "透视规范化：α = −(far+near)/(far−near)，β = −2·far·near/(far−near)",
    ),
    (
        "perspective projection onto y = −yl",
        "透视投影到平面 y = −yl",
    ),
    (
        "project from the light onto the plane y = 0",
        "从光源投影到平面 y = 0",
    ),
    (
        "rotation about an arbitrary axis, by aligning it with z",
        "绕任意轴旋转：先把轴对齐到 z 轴",
    ),
    (
        "rows u, v, n and −p·u, −p·v, −p·n with n = (eye−at)/|eye−at|, u = v_up×n/|v_up×n|, v = n×u; equals GAMES101's R_view·T_view with g = at − eye, t = up",
        "行为 u、v、n，最后一列为 −p·u、−p·v、−p·n，其中 n = (eye−at)/|eye−at|，u = v_up×n/|v_up×n|，v = n×u；等于 GAMES101 的 R_view·T_view（g = at − eye，t = up）",
    ),
    ("rows: g×t, t, −g", "各行：g×t、t、−g"),
    (
        "shear H(θ, φ): cot θ = (l+r)/(2·near), cot φ = (t+b)/(2·near)",
        "错切 H(θ, φ)：cot θ = (l+r)/(2·near)，cot φ = (t+b)/(2·near)",
    ),
    (
        "squish the frustum into a box (n and f fixed), then the orthographic projection",
        "先把视锥挤压成长方体（n 和 f 不变），再做正交投影",
    ),
    ("the joint", "关节"),
    (
        "the part's composite times its instance matrix",
        "部件的组合矩阵乘以其实例矩阵",
    ),
    ("the plane to y = 0", "把平面移到 y = 0"),
    ("the rotation itself, about z", "旋转本身：绕 z 轴"),
    ("to the joint", "移到关节"),
    ("undo the turn into the xz plane", "撤销转入 xz 平面的旋转"),
    ("undo the turn onto z", "撤销转到 z 轴的旋转"),
    ("where the figure stands", "人物所站的位置"),
    (
        "x' = n·x/z, y' = n·y/z; z of the near and far planes kept",
        "x' = n·x/z，y' = n·y/z；近平面和远平面的 z 保持不变",
    ),
    (
        "x_w = (x+1)·width/2, y_w = (y+1)·height/2, z_w = (z+1)/2",
        "x_w = (x+1)·width/2，y_w = (y+1)·height/2，z_w = (z+1)/2",
    ),
];

impl Lang {
    /// A matrix's formula in this language (formulas that are only mathematics are kept).
    #[must_use]
    pub fn formula(self, en: &str) -> String {
        match self.written() {
            super::Written::English => en.to_owned(),
            super::Written::Chinese => FORMULAS_ZH
                .iter()
                .find(|(e, _)| *e == en)
                .map_or_else(|| en.to_owned(), |(_, zh)| (*zh).to_owned()),
        }
    }
}
