<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DateTime time="12:00:00" date="2024-01-01"/>
  <User name="eulermap"/>
  <DataFileName name="spot.ply"/>
  <templateName name=""/>
 </DocumentData>
 <point x="0" y="0.300969" z="-0.668909" active="1" name="nose"/>
 <point x="0" y="-0.0809251" z="1.049" active="1" name="tail"/>
 <point x="-0.229681" y="-0.733842" z="0.0266899" active="1" name="hoof_front_left"/>
 <point x="0.229681" y="-0.733842" z="0.0266899" active="1" name="hoof_front_right"/>
 <point x="-0.198244" y="-0.736784" z="0.793448" active="1" name="hoof_back_left"/>
 <point x="0.198244" y="-0.736784" z="0.793448" active="1" name="hoof_back_right"/>
</PickedPoints>
