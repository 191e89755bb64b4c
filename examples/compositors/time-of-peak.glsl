// Time of peak: the time-step in which the density at the sample is highest (the earlier one on a
// tie), for the index TSTF to colour. The same as the built-in "time-of-max": a starting point for
// your own (docs/compositors.md lists the inputs and the rules).
int peak = -1;
for (int i = 0; i < count; ++i) {
    if (!hasData[i]) continue;  // no data at the sample in this time-step
    if (peak < 0 || density[i] > density[peak]) peak = i;
}
return float(peak);  // -1 where no time-step has data: nothing shows
