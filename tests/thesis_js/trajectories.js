/* SPDX-License-Identifier: MIT */
// tests/thesis_js/trajectories.js — the thesis's JavaScript for figures 10–14,
// transcribed faithfully, printing the CSV that the iskra examples print with
// --csv.  Run with node (IEEE doubles, like the browser the thesis used):
//
//     node tests/thesis_js/trajectories.js fig10            > fig10.csv
//     node tests/thesis_js/trajectories.js fig14 [frames]   (default 2000)
//     node tests/thesis_js/trajectories.js --selftest       (formatter check)
//
// Sources: the listings in the thesis (seed 000, §3.1–3.2) and the files of
// fsabolic/diplomski_rad as described in the catalogue (§1, §5.5–5.9): the
// classes Vektor2D, MaterijalnaTocka, SilaTeza, Otpor and Cestica, and the
// loops of putanja_cestice.html, putanja_s_otporom.html,
// putanja_sa_silom_tezom.html, putanja_s_otporom_i_tezom.html and
// animacija_putanja_s_otporom_i_tezom.html (dt 0.001 per frame in the file;
// the printed listing says 0.05).  Drawing is replaced by recording the
// position handed to gks.piksel; nothing else is changed.
//
// CSV: "step,drawn_x,drawn_y,x,y,vx,vy", one line per loop iteration
// (frame), step counted from 1, every number as C's printf("%.17g").
"use strict";

// ---- the thesis's classes ------------------------------------------------

class Vektor2D {
    constructor(x, y) {
        this.x = x;
        this.y = y;
    }
    zbroji(v2) {
        return new Vektor2D(this.x + v2.x, this.y + v2.y);
    }
    dodajCputaV(c, v) {
        this.x += c * v.x;
        this.y += c * v.y;
    }
}

class MaterijalnaTocka {
    constructor(masa, rVektor, vVektor) {
        this.masa = masa;
        this.r = rVektor;
        this.v = vVektor;
    }
    pomakni(dt, rezultantnaSila) {
        this.v.dodajCputaV(dt / this.masa, rezultantnaSila);
        this.r.dodajCputaV(dt, this.v);
    }
}

class SilaTeza {
    constructor(g) {
        this.g = g;
    }
    F(mt) {
        return new Vektor2D(0, mt.masa * -this.g);
    }
}

class Otpor {
    constructor(o) {
        this.o = o;
    }
    F(materijalnaTocka) {
        return new Vektor2D(-this.o * materijalnaTocka.v.x, -this.o * materijalnaTocka.v.y);
    }
}

// GlobalniKoordinatniSustav, reduced to what the loops use: the view window
// and piksel(), which here records the drawn world position.
class GlobalniKoordinatniSustav {
    constructor(xmin, xmax, ymin, ymax) {
        this.xmin = xmin;
        this.xmax = xmax;
        this.ymin = ymin;
        this.ymax = ymax;
        this.drawn = null;
    }
    piksel(x, y, boja) {
        this.drawn = [x, y];
    }
    ocisti() {}
}

class Cestica {
    constructor(promjer, materijalnaTocka, boja = "yellow") {
        this.materijalnaTocka = materijalnaTocka;
        this.boja = boja;
        this.promjer = promjer;
    }
    zarobi(gks, top = true, right = true, bottom = true, left = true) {
        if (this.materijalnaTocka.r.x < gks.xmin + this.promjer && left) {
            this.materijalnaTocka.v.x = -this.materijalnaTocka.v.x;
        }
        if (this.materijalnaTocka.r.x > gks.xmax - this.promjer && right) {
            this.materijalnaTocka.v.x = -this.materijalnaTocka.v.x;
        }
        if (this.materijalnaTocka.r.y < gks.ymin + this.promjer && bottom) {
            this.materijalnaTocka.v.y = -this.materijalnaTocka.v.y;
        }
        if (this.materijalnaTocka.r.y > gks.ymax - this.promjer && top) {
            this.materijalnaTocka.v.y = -this.materijalnaTocka.v.y;
        }
        if (this.materijalnaTocka.r.y < gks.ymin + this.promjer && bottom) {
            this.materijalnaTocka.r.y = gks.ymin + this.promjer;
        }
    }
    iscrtaj(gks) {
        gks.piksel(this.materijalnaTocka.r.x, this.materijalnaTocka.r.y, this.boja);
    }
}

// ---- C's printf("%.17g"), exactly ------------------------------------------
// The double is expanded to its exact decimal value with BigInt, rounded to
// 17 significant digits half-to-even (glibc rounds the exact value in the
// default rounding mode), then laid out as %g: exponent form when the decimal
// exponent is < -4 or >= 17, trailing zeros (and a bare point) removed,
// exponent with a sign and at least two digits.
function formatG17(x) {
    const P = 17;
    if (Number.isNaN(x)) return "nan"; // glibc prints -nan for a negative NaN; never needed here
    const neg = x < 0 || Object.is(x, -0);
    const sign = neg ? "-" : "";
    if (!Number.isFinite(x)) return sign + "inf";
    if (x === 0) return sign + "0";
    const dv = new DataView(new ArrayBuffer(8));
    dv.setFloat64(0, Math.abs(x));
    const bits = dv.getBigUint64(0);
    const bexp = Number((bits >> 52n) & 0x7ffn);
    let mant = bits & ((1n << 52n) - 1n);
    let e2;
    if (bexp === 0) {
        e2 = -1074; // subnormal
    } else {
        mant |= 1n << 52n;
        e2 = bexp - 1075;
    }
    // exact value = digits * 10^-scale
    let digits, scale;
    if (e2 >= 0) {
        digits = (mant << BigInt(e2)).toString();
        scale = 0;
    } else {
        digits = (mant * 5n ** BigInt(-e2)).toString();
        scale = -e2;
    }
    digits = digits.replace(/^0+/, "");
    let exp10 = digits.length - 1 - scale; // value = d.ddd * 10^exp10
    if (digits.length > P) {
        let head = BigInt(digits.slice(0, P));
        const rest = digits.slice(P);
        const first = rest.charCodeAt(0) - 48;
        const tail = /[1-9]/.test(rest.slice(1));
        if (first > 5 || (first === 5 && (tail || head % 2n === 1n))) head += 1n;
        let h = head.toString();
        if (h.length > P) {
            // 99..9 rounded up to 100..0
            h = h.slice(0, P);
            exp10 += 1;
        }
        digits = h;
    }
    digits = digits.padEnd(P, "0");
    let out;
    if (exp10 < -4 || exp10 >= P) {
        let frac = digits.slice(1).replace(/0+$/, "");
        const es = exp10 < 0 ? "-" : "+";
        const ea = Math.abs(exp10).toString().padStart(2, "0");
        out = digits[0] + (frac ? "." + frac : "") + "e" + es + ea;
    } else if (exp10 >= 0) {
        const ip = digits.slice(0, exp10 + 1);
        const fp = digits.slice(exp10 + 1).replace(/0+$/, "");
        out = ip + (fp ? "." + fp : "");
    } else {
        const fp = ("0".repeat(-exp10 - 1) + digits).replace(/0+$/, "");
        out = "0." + fp;
    }
    return sign + out;
}

// ---- the figures' loops ------------------------------------------------------

function row(out, step, gks, cestica) {
    const mt = cestica.materijalnaTocka;
    out.push(
        [step, gks.drawn[0], gks.drawn[1], mt.r.x, mt.r.y, mt.v.x, mt.v.y]
            .map((v, i) => (i === 0 ? String(v) : formatG17(v)))
            .join(",")
    );
}

function newParticle() {
    return new Cestica(0.1, new MaterijalnaTocka(1, new Vektor2D(-4, -4), new Vektor2D(1, -2)));
}

// fig 10: putanja_cestice.html
function fig10(out) {
    let gks = new GlobalniKoordinatniSustav(-10, 10, -10, 10);
    let cestica = newParticle();
    let dt = 0.25;
    for (let i = 0; i < 1000; i++) {
        cestica.materijalnaTocka.pomakni(dt, new Vektor2D(0, 0));
        cestica.iscrtaj(gks);
        cestica.zarobi(gks, false, false, true, false);
        row(out, i + 1, gks, cestica);
    }
}

// fig 11: putanja_s_otporom.html
function fig11(out) {
    let gks = new GlobalniKoordinatniSustav(-10, 10, -10, 10);
    let cestica = newParticle();
    let otporSredstva = new Otpor(0.1);
    let dt = 0.25;
    for (let i = 0; i < 1000; i++) {
        const silaOtpora = otporSredstva.F(cestica.materijalnaTocka);
        cestica.materijalnaTocka.pomakni(dt, silaOtpora);
        cestica.iscrtaj(gks);
        cestica.zarobi(gks, false, false, true, false);
        row(out, i + 1, gks, cestica);
    }
}

// fig 12: putanja_sa_silom_tezom.html
function fig12(out) {
    let gks = new GlobalniKoordinatniSustav(-10, 10, -10, 10);
    let cestica = newParticle();
    let silaTeza = new SilaTeza(0.25);
    let dt = 0.25;
    for (let i = 0; i < 1000; i++) {
        const sila = silaTeza.F(cestica.materijalnaTocka);
        cestica.materijalnaTocka.pomakni(dt, sila);
        cestica.iscrtaj(gks);
        cestica.zarobi(gks, false, false, true, false);
        row(out, i + 1, gks, cestica);
    }
}

// fig 13: putanja_s_otporom_i_tezom.html
function fig13(out) {
    let gks = new GlobalniKoordinatniSustav(-10, 10, -10, 10);
    let cestica = newParticle();
    let silaTeza = new SilaTeza(0.25);
    let otporSredstva = new Otpor(0.1);
    let dt = 0.25;
    for (let i = 0; i < 1000; i++) {
        const sila = silaTeza.F(cestica.materijalnaTocka);
        const silaOtpora = otporSredstva.F(cestica.materijalnaTocka);
        cestica.materijalnaTocka.pomakni(dt, sila.zbroji(silaOtpora));
        cestica.iscrtaj(gks);
        cestica.zarobi(gks, false, false, true, false);
        row(out, i + 1, gks, cestica);
    }
}

// fig 14: animacija_putanja_s_otporom_i_tezom.html — render() once per
// animation frame; here `frames` calls in a row.
function fig14(out, frames) {
    let gks = new GlobalniKoordinatniSustav(-10, 10, -10, 10);
    let cestica = newParticle();
    let silaTeza = new SilaTeza(0.25);
    let otporSredstva = new Otpor(0.1);
    let dt = 0.001;
    let frame = 0;
    function render() {
        gks.ocisti();
        const sila = silaTeza.F(cestica.materijalnaTocka);
        const silaOtpora = otporSredstva.F(cestica.materijalnaTocka);
        cestica.materijalnaTocka.pomakni(dt, sila.zbroji(silaOtpora));
        cestica.iscrtaj(gks);
        cestica.zarobi(gks, false, false, true, false);
        row(out, ++frame, gks, cestica);
    }
    for (let f = 0; f < frames; f++) render(); // requestAnimationFrame(render)
}

// ---- formatter self-test values (bits in hex, then the formatted text) ------
function selftest(out) {
    const vals = [
        0, -0, 1, -1, 0.1, 0.25, -9.9, 1 / 3, 2 / 3, 1e-5, 1.5e-5, 0.0001, 0.00012345, 1e16, 1e17,
        123456789012345678, 1.7976931348623157e308, 5e-324, 2.2250738585072014e-308, 9.999999999999999e22,
        0.30000000000000004, 100, 1e21, 12345.678, -3.4384e-7, 5.75, 3.4384, Math.PI, Math.E, 2 ** -30,
        2 ** 60, 2 ** 63 + 2 ** 11, 0.5, 1e-4 * 3, 99999999999999999, 9.5367431640625e-7, 4.35,
        // ties at the 18th digit: 2^-k*m with exactly 18 significant digits
        1.00000000000000005e-1, 0.000123, 123456.7890123456789,
    ];
    const dv = new DataView(new ArrayBuffer(8));
    for (let k = 0; k < 2000; k++) {
        // pseudo-random bit patterns (fixed LCG) over all exponents
        const hi = (Math.imul(k + 1, 2654435761) >>> 0) & 0x7fefffff;
        const lo = Math.imul(k + 7, 40503) >>> 0;
        dv.setUint32(0, hi);
        dv.setUint32(4, lo);
        vals.push(dv.getFloat64(0));
        vals.push(-dv.getFloat64(0) / 3);
    }
    for (const v of vals) {
        dv.setFloat64(0, v);
        const h = dv.getBigUint64(0).toString(16).padStart(16, "0");
        out.push(h + " " + formatG17(v));
    }
}

function main(argv) {
    const which = argv[0];
    const out = [];
    if (which === "--selftest") {
        selftest(out);
    } else {
        out.push("step,drawn_x,drawn_y,x,y,vx,vy");
        if (which === "fig10") fig10(out);
        else if (which === "fig11") fig11(out);
        else if (which === "fig12") fig12(out);
        else if (which === "fig13") fig13(out);
        else if (which === "fig14") {
            const n = argv.length > 1 ? Number(argv[1]) : 2000;
            if (!Number.isInteger(n) || n < 0) {
                process.stderr.write("frames must be a whole number\n");
                process.exit(2);
            }
            fig14(out, n);
        } else {
            process.stderr.write("usage: node trajectories.js fig10|fig11|fig12|fig13|fig14 [frames]|--selftest\n");
            process.exit(2);
        }
    }
    process.stdout.write(out.join("\n") + "\n");
}

main(process.argv.slice(2));
