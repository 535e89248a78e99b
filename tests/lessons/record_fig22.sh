#!/bin/sh
# SPDX-License-Identifier: MIT
# Records tests/lessons/fig22.txt, the figure 22 lesson, as a teacher
# would with `iskra play --record`, but driven by a --script under SDL's
# dummy video driver (no display needed), then writes its references
# tests/lessons/fig22/*.png with `iskra replay --update`.  Run it from the
# repository root only to change the lesson on purpose; the tests
# (tests/test_lessons.c) check the committed files.
#     tests/lessons/record_fig22.sh [ISKRA]      (default build/bin/iskra)
set -eu
bin=${1:-build/bin/iskra}
lesson=tests/lessons/fig22.txt
refs=tests/lessons/fig22

# The lesson: a Gauss explosion; gravity and drag typed into the console;
# three walls; checkpoint 1.  A ring explosion; a potential added and its
# k typed; checkpoint 2.  The potential's disc dragged across the canvas
# by hand (press, pointer moves over several frames, release); checkpoint
# 3.  Then the particles settle under the potential; checkpoint 4.
# F9 is the recorder's checkpoint key (shot:checkpoint-N).
drag=""
x=200
y=400
while [ $x -lt 360 ]; do
    x=$((x + 20))
    y=$((y - 10))
    drag="$drag move:$x,$y wait:1"
done

SDL_VIDEODRIVER=dummy "$bin" play fig22_simulator_regular --screen 1366x768 --fixed-clock \
    --record "$lesson" --script "wait:20 \
press:click/gauss wait:2 click:300,300 wait:40 \
press:gravity wait:2 type:5 key:return wait:2 \
press:drag wait:2 type:0.5 key:return wait:2 \
press:wall-bottom wait:2 press:wall-left wait:2 press:wall-right wait:30 \
f9 wait:2 \
press:click/ring wait:2 click:400,200 wait:30 \
press:click/add-potential wait:2 click:200,400 wait:2 \
press:pot-k wait:2 type:40 key:return wait:10 \
f9 wait:2 \
down:200,400 wait:1 $drag up:$x,$y wait:30 \
f9 wait:2 wait:60 \
f9 wait:2 quit"
"$bin" replay "$lesson" --check "$refs" --update
