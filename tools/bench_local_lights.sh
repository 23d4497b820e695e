# The local lights of tools/bench_local.sh and tools/bench_local_gles.sh
# (sourced by both, so that the CPU and GLES tables measure the same
# scenes): X,Y,Z,R,LE for the 128x128 cones and panel, brightest first.
CONES=(64,64,12,2,100 20,20,6,1.5,60 100,110,25,3,150 50,110,4,1,40 110,60,8,1,50 70,15,3,1,30 30,70,15,2,80 90,80,30,4,200)
PANEL=(48,48,7,1.5,50 80,20,6,1,40 20,80,9,2,60 112,100,3,0.8,30 60,90,8,1,50 16,16,6,1,40 100,48,10,2,80 40,110,5,1,40)
